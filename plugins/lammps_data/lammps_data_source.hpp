#pragma once
// One frame from a LAMMPS data file of spheres (data_file.hpp). A data file holds no walls
// (LAMMPS puts them in the input script), so the container is given here: the data file's
// box with walls, an open top, and a vertical cylinder when `cylinder_radius` > 0, its base
// at `base`. A particle outside that container (through a wall by more than
// kWallTolerance of its radius, or above the top) is refused: a DEM run from it would fire
// it back in.
#include "granpipe/plugin.hpp"

namespace granpipe::lammps_data {

// The overlap with a wall accepted as touching, in radii: settled soft-sphere packings
// press into their walls by up to a few percent of a radius (data-samples: 0.6 % at rest,
// 2.6 % in a shaken bed).
constexpr double kWallTolerance = 0.05;

Schema schema();

class LammpsDataSource : public Source {
 public:
  explicit LammpsDataSource(const PluginContext& ctx);
  FrameContent content() const override { return {.dim = 3}; }
  Work work() const override { return {.total = 1}; }
  bool next(Frame& frame) override;

 private:
  Frame frame_;
  bool done_ = false;
};

}  // namespace granpipe::lammps_data
