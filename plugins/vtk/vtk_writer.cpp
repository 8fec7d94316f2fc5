#include "vtk_writer.hpp"

#include <cstdio>

#include "granpipe/atomic_file.hpp"
#include "vtk_polydata.hpp"

namespace granpipe::vtk {

VtkWriter::VtkWriter(const PluginContext& ctx) : dir_(ctx.output_dir), name_(ctx.name) {}

void VtkWriter::write(const Frame& frame) {
  char number[24];
  std::snprintf(number, sizeof number, "_%06zu.vtp", written_.size());
  const std::string file = name_ + number;
  write_file_atomically(dir_ / file, polydata_xml(frame));
  written_.push_back({frame.time, frame.step, file});
}

void VtkWriter::close() {
  if (written_.empty()) return;  // no frame: no collection
  write_file_atomically(dir_ / (name_ + ".pvd"), collection_xml(written_));
}

}  // namespace granpipe::vtk
