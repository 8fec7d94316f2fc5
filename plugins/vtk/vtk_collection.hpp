#pragma once
// The ParaView collection (.pvd) of a run's .vtp files: one DataSet per frame, in order.
#include <cstdint>
#include <string>
#include <vector>

namespace granpipe::vtk {

struct WrittenFrame {
  double time = 0.0;
  std::int64_t step = 0;
  std::string file;  // relative to the .pvd
};

// The timestep of each frame: its time when times increase from frame to frame, else its
// step when steps do, else its index (a viewer merges frames of equal timestep).
std::vector<double> timesteps(const std::vector<WrittenFrame>& frames);

std::string collection_xml(const std::vector<WrittenFrame>& frames);

}  // namespace granpipe::vtk
