#pragma once
// Which of a file's frames a reading source yields: `first`, `last` and `stride`, declared
// once here so that every source reading saved frames (H5MD files, LAMMPS dumps) takes the
// same parameters with the same meaning and the same refusals.
#include <string>

#include "granpipe/params.hpp"
#include "granpipe/plugin.hpp"

namespace granpipe {

// Adds first, last and stride to a source's schema.
void declare_frame_selection(Schema& s);

// Frames first, first + stride, ... up to last (inclusive), as indices into the file.
struct FrameSelection {
  long first = 0, last = 0, stride = 1;
  long count() const { return (last - first) / stride + 1; }
};

// The selection the parameters make of a file of `frames` frames (last = -1: its last).
// InputError naming the parameter when it lies outside the file; `held` ends those
// messages, e.g. " (frames.h5 holds 4 frames)".
FrameSelection select_frames(const PluginContext& ctx, long frames, const std::string& held);

}  // namespace granpipe
