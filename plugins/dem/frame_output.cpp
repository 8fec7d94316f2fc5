#include "frame_output.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include "granpipe/errors.hpp"

namespace granpipe::dem {

namespace {

struct ContactRow {
  std::int64_t i, j;
  double overlap;
  Vec3 normal, tangential, point;
};

void pair_contacts(const Engine& e, std::vector<ContactRow>& rows) {
  const Particles& p = e.particles();
  const NeighborList& list = e.neighbors();
  for (int a = 0; a < p.size(); ++a) {
    for (std::int32_t k = list.first[a]; k < list.first[a + 1]; ++k) {
      const int b = list.partner[k];
      const Vec3 d = p.x.col(a) - p.x.col(b);
      const double contact = p.radius[a] + p.radius[b];
      // The force loop's test, on the same positions: the same contacts.
      if (d.squaredNorm() >= contact * contact) continue;
      const double r = d.norm();
      const Vec3 n = d / r;
      const double* reaction = &list.reaction[static_cast<std::size_t>(list.reaction_stride) * k];
      const Vec3 on_a = -Vec3(reaction[0], reaction[1], reaction[2]);
      const Vec3 normal = on_a.dot(n) * n;
      const double overlap = contact - r;
      const Vec3 point = p.x.col(a) - (p.radius[a] - 0.5 * overlap) * n;
      // Rows name the smaller index first, with the forces on it.
      const double sign = p.tag[a] < p.tag[b] ? 1.0 : -1.0;
      rows.push_back({std::min(p.tag[a], p.tag[b]), std::max(p.tag[a], p.tag[b]), overlap,
                      sign * normal, sign * (on_a - normal), point});
    }
  }
}

void wall_contacts(const Engine& e, std::vector<ContactRow>& rows) {
  const Particles& p = e.particles();
  const Eigen::Vector3d offset = e.wall_offset();
  for (int slot = 0; slot < e.walls().count(); ++slot) {
    const std::int64_t wall = partner::wall(e.walls().wall_of_slot(slot));
    for (int a = 0; a < p.size(); ++a) {
      Vec3 n;
      const double overlap = e.walls().overlap(slot, p.x.col(a), p.radius[a], offset, n);
      if (overlap <= 0.0) continue;
      const Vec3 point = p.x.col(a) - (p.radius[a] - 0.5 * overlap) * n;
      rows.push_back({p.tag[a], wall, overlap, e.recorded_wall_normal()[slot].col(a),
                      e.recorded_wall_tangential()[slot].col(a), point});
    }
  }
}

void fill_particles(const Particles& p, Frame& frame) {
  frame.resize(p.size(), 3);
  Coordinates& x = frame.position();
  auto& v = frame.add("velocity").as<Coordinates>();
  auto& w = frame.add("angular_velocity").as<Coordinates>();
  for (int a = 0; a < p.size(); ++a) {
    const std::int32_t row = p.tag[a];
    x.row(row) = p.x.col(a).transpose();
    v.row(row) = p.v.col(a).transpose();
    w.row(row) = p.omega.col(a).transpose();
    frame.radius()[row] = p.radius[a];
    frame.species()[row] = p.species[a];
  }
}

void fill_contacts(std::vector<ContactRow>& rows, Frame& frame) {
  std::sort(rows.begin(), rows.end(), [](const ContactRow& a, const ContactRow& b) {
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  PropertyTable& table = frame.add_contacts(static_cast<Eigen::Index>(rows.size()));
  auto& overlap = table.add<Eigen::ArrayXd>(*find_standard("overlap", Scope::Contact));
  auto& normal = table.add<Coordinates>(*find_standard("normal_force", Scope::Contact));
  auto& tangential = table.add<Coordinates>(*find_standard("tangential_force", Scope::Contact));
  auto& point = table.add<Coordinates>(*find_standard("point", Scope::Contact));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto r = static_cast<Eigen::Index>(k);
    frame.contact_i()[r] = rows[k].i;
    frame.contact_j()[r] = rows[k].j;
    overlap[r] = rows[k].overlap;
    normal.row(r) = rows[k].normal.transpose();
    tangential.row(r) = rows[k].tangential.transpose();
    point.row(r) = rows[k].point.transpose();
  }
}

// The drive's phase and the container's velocity, for analyses that cut a run into cycles.
void add_drive_observables(const Drive& drive, double t, Frame& frame) {
  static const Property cycles{
      "cycles", Scope::Frame, ValueType::Real,
      1,        "1",          "drive periods since the drive started, (t - start) f"};
  static const Property velocity{
      "container_velocity", Scope::Frame,
      ValueType::Real,      1,
      "length/time",        "vertical velocity of the vibrating container"};
  frame.set_observable(cycles, drive.cycles(t));
  frame.set_observable(velocity, drive.velocity(t)[2]);
}

}  // namespace

void fill_frame(const Engine& engine, Frame& frame) {
  if (engine.walls().count() > 0 && !engine.contacts_recorded()) {
    throw InternalError("dem: fill_frame at step " + std::to_string(engine.step()) +
                        ": the wall contacts of this step were not recorded "
                        "(Engine::record_contacts(true) before the last step)");
  }
  fill_particles(engine.particles(), frame);
  std::vector<ContactRow> rows;
  pair_contacts(engine, rows);
  wall_contacts(engine, rows);
  fill_contacts(rows, frame);
  frame.container = engine.walls().at(engine.time());
  add_drive_observables(engine.walls().drive(), engine.time(), frame);
  frame.time = engine.time();
  frame.step = engine.step();
}

}  // namespace granpipe::dem
