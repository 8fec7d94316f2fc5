#include "lammps_data_source.hpp"

#include <fstream>

#include "data_file.hpp"
#include "granpipe/deepest_overlap.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/stated_container.hpp"

namespace granpipe::lammps_data {

namespace {

// write_data of a 2D run puts every atom at z = 0 in a box about an atom thick along z: disks,
// which 3D analyzers would measure as spheres (exit 0). No 3D packing fits in a box no thicker
// than an atom's diameter; the lammps_dump source refuses such dumps alike.
void refuse_a_2d_run(const Frame& f, const std::string& file) {
  const auto z = f.position().col(2);
  const double diameter = 2.0 * f.radius().maxCoeff(), thick = f.container.length(2);
  if (thick > diameter || (z != z[0]).any()) return;
  throw InputError(file + ": expected a 3D packing (granpipe's LAMMPS readers read 3D runs), got " +
                   "every atom at z = " + format_number(z[0]) + " in a box " +
                   format_number(thick) + " thick (zlo zhi), no more than an atom's diameter (" +
                   format_number(diameter) + "): a 2D run's data file");
}

}  // namespace

Schema schema() {
  Schema s;
  s.path("file", std::nullopt, "LAMMPS data file (atom_style sphere)");
  declare_stated_container(s);
  declare_max_overlap(s, 0.3,
                      "a sound soft-sphere run stays within 0.3; a file with a deeper one (atoms "
                      "stacked at one place) is refused");
  return s;
}

LammpsDataSource::LammpsDataSource(const PluginContext& ctx) {
  const std::string file = ctx.params.string("file");
  const StatedContainer stated(ctx);
  std::ifstream in(file);
  if (!in) throw InputError(ctx.param("file") + ": cannot read " + file);
  frame_ = read_atoms(in, file);
  if (frame_.size() == 0) throw InputError(file + ": expected atoms, got none");
  frame_.check(file);
  refuse_a_2d_run(frame_, file);
  // Without a cylinder or side walls, the x and y sides are the file's box, open.
  const Container file_box = frame_.container;
  frame_.container = stated.place(file_box, file);
  if (const auto out = stated.first_outside(frame_, file_box, "the data file's box")) {
    throw InputError(file + ": " + out->message);
  }
  refuse_deep_overlap(frame_, ctx.params.real("max_overlap"), ctx.param("max_overlap"), "", file);
}

bool LammpsDataSource::next(Frame& frame) {
  if (done_) return false;
  frame = frame_;
  done_ = true;
  return true;
}

}  // namespace granpipe::lammps_data
