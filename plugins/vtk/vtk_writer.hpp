#pragma once
// The vtk writer: <name>_<frame>.vtp per saved frame (frame = 0, 1, ... in the order
// written), each written under a temporary name and renamed once complete, and at the end
// of the run <name>.pvd listing them, so a run stopped early leaves complete frames and no
// collection that claims to be whole. Each file names the run that wrote it in a comment.
#include <filesystem>
#include <string>
#include <vector>

#include "granpipe/plugin.hpp"
#include "vtk_collection.hpp"

namespace granpipe::vtk {

// `xml` with a comment holding `provenance` after its XML declaration: which run wrote it.
std::string with_provenance(std::string xml, const std::string& provenance);

class VtkWriter : public Writer {
 public:
  explicit VtkWriter(const PluginContext& ctx);
  void write(const Frame& frame) override;
  void close() override;

 private:
  OutputFiles files_;
  std::string provenance_;
  std::vector<WrittenFrame> written_;
};

}  // namespace granpipe::vtk
