#pragma once
// Frames as extended XYZ: per frame a count line, a comment line with the box
// (Lattice=..., its lower corner as Origin=...), which sides are periodic (pbc=...), the
// time, the step, the list of
// columns (Properties=...) and the run that wrote it (granpipe=...), then one line per
// particle. Every particle column of the frame
// is written, the published ones included, so that OVITO or ASE see what granpipe saw.
#include <cstdio>
#include <filesystem>
#include <string>

#include "granpipe/plugin.hpp"

namespace granpipe::xyz {

// The comment line of a frame (without the newline), before the writer adds granpipe=.
std::string comment_line(const Frame& frame);
// One particle's line (without the newline); `digits` significant digits for reals.
std::string particle_line(const Frame& frame, Eigen::Index i, int digits);

class XyzWriter : public Writer {
 public:
  explicit XyzWriter(const PluginContext& ctx);
  ~XyzWriter() override;
  void write(const Frame& frame) override;
  void close() override;

 private:
  std::filesystem::path final_path_, partial_path_;
  int digits_;
  std::string provenance_;  // the comment line's last key: granpipe="granpipe 0.1.0 commit ..."
  std::FILE* file_ = nullptr;
};

}  // namespace granpipe::xyz
