#pragma once
// One frame from a LAMMPS data file of spheres (data_file.hpp). A data file holds no walls
// (LAMMPS puts them in the input script), so the container is stated in the pipeline
// (granpipe/stated_container.hpp): a vertical cylinder or side walls, a base and an open
// top; without a cylinder or side walls, x and y sides that hold every particle. A particle
// outside that container (through a wall by more than kStatedWallTolerance of its radius,
// or above the top) is refused: a DEM run from it would fire it back in.
#include "granpipe/plugin.hpp"

namespace granpipe::lammps_data {

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
