#include "vtk_collection.hpp"

#include <cmath>
#include <cstdio>

namespace granpipe::vtk {

namespace {

template <class Value>
bool increasing(const std::vector<WrittenFrame>& frames, Value WrittenFrame::*value) {
  for (std::size_t k = 1; k < frames.size(); ++k) {
    if (!(frames[k].*value > frames[k - 1].*value)) return false;
  }
  return true;
}

// Times that are numbers: an undefined one (NaN: a dump read without dt) made the timestep
// of a single frame "nan", which ParaView cannot read.
bool defined_times(const std::vector<WrittenFrame>& frames) {
  for (const WrittenFrame& f : frames)
    if (!std::isfinite(f.time)) return false;
  return true;
}

}  // namespace

std::vector<double> timesteps(const std::vector<WrittenFrame>& frames) {
  std::vector<double> t;
  const bool by_time = defined_times(frames) && increasing(frames, &WrittenFrame::time);
  const bool by_step = increasing(frames, &WrittenFrame::step);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    t.push_back(by_time   ? frames[k].time
                : by_step ? static_cast<double>(frames[k].step)
                          : static_cast<double>(k));
  }
  return t;
}

std::string collection_xml(const std::vector<WrittenFrame>& frames) {
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  const std::vector<double> t = timesteps(frames);
  char timestep[32];
  for (std::size_t k = 0; k < frames.size(); ++k) {
    std::snprintf(timestep, sizeof timestep, "%.17g", t[k]);
    text += std::string("    <DataSet timestep=\"") + timestep + "\" part=\"0\" file=\"" +
            frames[k].file + "\"/>\n";
  }
  return text + "  </Collection>\n</VTKFile>\n";
}

}  // namespace granpipe::vtk
