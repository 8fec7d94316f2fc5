#include "lammps_data_source.hpp"

#include <fstream>

#include "data_file.hpp"
#include "granpipe/deepest_overlap.hpp"
#include "granpipe/stated_container.hpp"

namespace granpipe::lammps_data {

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
