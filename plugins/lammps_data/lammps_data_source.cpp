#include "lammps_data_source.hpp"

#include <fstream>

#include "data_file.hpp"
#include "granpipe/deepest_overlap.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/stated_container.hpp"

namespace granpipe::lammps_data {

namespace {

// write_data of a 2D run puts every atom at z = 0, in a box whose z bounds straddle it
// (LAMMPS requires so of a 2D run, -0.5 to 0.5 whatever the atoms' size): disks, which 3D
// analyzers would measure as spheres (exit 0). A data file states no periodic flags, so the
// dump's test (a box periodic along z) is not the data's, and nothing tells such a file from
// a 3D packing lying in the plane z = 0 (two spheres set for a head-on collision): the
// message says how to have that one read.
void refuse_a_2d_run(const Frame& f, const Container& box, const std::string& file) {
  const auto z = f.position().col(2);
  if ((z != 0.0).any() || !(box.lo[2] < 0.0 && box.hi[2] > 0.0)) return;
  throw InputError(file + ": expected a 3D packing (granpipe's LAMMPS readers read 3D runs), got " +
                   "every atom at z = 0 in a box from zlo " + format_number(box.lo[2]) +
                   " to zhi " + format_number(box.hi[2]) +
                   ": a 2D run's data file (a 3D packing in the plane z = 0 cannot be told from "
                   "one: shift its atoms and box off z = 0 to have it read)");
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
  refuse_a_2d_run(frame_, frame_.container, file);
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
