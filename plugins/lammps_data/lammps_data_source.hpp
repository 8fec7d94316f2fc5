#pragma once
// One frame from a LAMMPS data file written for atom_style sphere (read_data/write_data):
// the "Atoms" section's lines "id type diameter density x y z [ix iy iz]", in id order; the
// species is type - 1. A data file holds no walls (LAMMPS puts them in the input script),
// so the container is given here: the data file's box with walls, an open top, and a
// vertical cylinder when `cylinder_radius` > 0, its base at `base`.
#include <filesystem>
#include <istream>

#include "granpipe/plugin.hpp"

namespace granpipe::lammps_data {

Schema schema();

// The particles of a data file; InputError naming `where` and the line on a malformed one.
Frame read_atoms(std::istream& in, const std::string& where);

class LammpsDataSource : public Source {
 public:
  explicit LammpsDataSource(const PluginContext& ctx);
  FrameContent content() const override { return {.dim = 3}; }
  bool next(Frame& frame) override;

 private:
  Frame frame_;
  bool done_ = false;
};

}  // namespace granpipe::lammps_data
