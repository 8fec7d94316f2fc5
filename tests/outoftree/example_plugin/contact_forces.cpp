// contact_forces.cpp: the mean normal force between particles, read from the standard
// contact column, and the fabric tensor of the contact normals, reported as a table.
// The README shows this file; the out-of-tree test builds it.
#include <cmath>
#include <granpipe/plugin.hpp>
#include <string>
#include <vector>

namespace {

class ContactForces : public granpipe::Analyzer {
 public:
  explicit ContactForces(const granpipe::PluginContext&) {}

  // A contact table with the standard normal_force column (docs/file-format.md).
  granpipe::FrameContent needs() const override {
    return {.contacts = true,
            .columns = {*granpipe::find_standard("normal_force", granpipe::Scope::Contact)}};
  }

  void consume(const granpipe::Frame& frame, granpipe::FrameCache&) override {
    // One row per contact, one column per axis: a ValueTable, as every [dim] column.
    const auto& force = frame.contacts->get<granpipe::ValueTable<double>>("normal_force");
    dim_ = frame.dim;
    for (Eigen::Index c = 0; c < force.rows(); ++c) {
      if (!granpipe::partner::is_particle(frame.contact_j()[c])) continue;  // a wall
      const Eigen::VectorXd f = force.row(c).matrix().transpose();
      if (f.norm() == 0) continue;  // touching, not pressed: no direction
      magnitude_.add(f.norm());
      fabric_.topLeftCorner(dim_, dim_) += f * f.transpose() / f.squaredNorm();
      ++contacts_;
    }
  }

  void finish(granpipe::Results& results) override {
    results.add_scalar("contacts", static_cast<double>(contacts_), std::nan(""), "",
                       "pressed particle-particle contacts, all frames");
    if (contacts_ == 0) return;  // no mean or tensor of nothing
    results.add_mean("normal_force", magnitude_, "force", "mean |normal force| between particles");
    // A tensor: one table row per tensor row, one column per component.
    const char* axes[] = {"x", "y", "z"};
    std::vector<std::string> columns{"row"};
    for (int b = 0; b < dim_; ++b) columns.push_back(axes[b]);
    granpipe::Table fabric(columns, "fabric tensor <n n> of the normals of pressed contacts");
    for (int a = 0; a < dim_; ++a) {
      std::vector<double> row{static_cast<double>(a)};
      for (int b = 0; b < dim_; ++b) row.push_back(fabric_(a, b) / static_cast<double>(contacts_));
      fabric.add_row(row);
    }
    results.add_table("fabric", std::move(fabric));
  }

 private:
  int dim_ = 3;
  long contacts_ = 0;
  granpipe::RunningMean magnitude_;
  Eigen::Matrix3d fabric_ = Eigen::Matrix3d::Zero();
};

}  // namespace

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<ContactForces>("contact_forces", "mean normal force, fabric tensor",
                                       granpipe::Schema{});
}
