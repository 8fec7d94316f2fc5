#pragma once
// The saved frame a source starts from: frame `initial_frame` (-1: the last) of the H5MD
// file `initial_file`, two parameters every source that can continue a run declares. One
// reader for them, so that each source refuses a missing frame in the same words and
// names the parameter at fault, and none ignores `initial_frame` given without a file
// (a start meant to continue a run would silently begin a new one).
#include <optional>
#include <string>

#include "granpipe/frame.hpp"
#include "granpipe/plugin.hpp"

namespace granpipe {

struct StartFrame {
  Frame frame;
  long index = 0;              // in the file
  std::string where;           // "source.params.initial_file: <file>: frame <k>", to begin messages
  bool radii_stored = true;    // false: the file has none, every radius is the default given
  bool species_stored = true;  // false: the file has none, every species is 0
};

// Nothing when `initial_file` is empty. Throws InputError naming `initial_frame` when it
// is set without a file or past the file's last frame, and `initial_file` when the file
// cannot be read as H5MD or holds no frame. `default_radius` is for files without radii.
std::optional<StartFrame> read_start_frame(const PluginContext& ctx, double default_radius = 0.5);

}  // namespace granpipe
