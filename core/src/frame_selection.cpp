#include "granpipe/frame_selection.hpp"

namespace granpipe {

void declare_frame_selection(Schema& s) {
  s.integer("first", 0, "index of the first frame read (0: the first in the file)").min(0);
  s.integer("last", -1, "index of the last frame read, inclusive (-1: the last in the file)")
      .min(-1);
  s.integer("stride", 1, "read every stride-th frame from first on").min(1);
}

FrameSelection select_frames(const PluginContext& ctx, long frames, const std::string& held) {
  FrameSelection s{static_cast<long>(ctx.params.integer("first")),
                   static_cast<long>(ctx.params.integer("last")),
                   static_cast<long>(ctx.params.integer("stride"))};
  if (s.first >= frames) {
    throw InputError(ctx.param("first") + ": expected a frame index below " +
                     std::to_string(frames) + ", got " + std::to_string(s.first) + held);
  }
  if (s.last == -1) s.last = frames - 1;
  if (s.last >= frames) {
    throw InputError(ctx.param("last") + ": expected -1 or a frame index below " +
                     std::to_string(frames) + ", got " + std::to_string(s.last) + held);
  }
  if (s.last < s.first) {
    throw InputError(ctx.param("last") + ": expected -1 or an index >= first (" +
                     std::to_string(s.first) + "), got " + std::to_string(s.last));
  }
  // A longer stride reads the first frame only, as this one does; it would overflow the
  // frame index.
  if (s.stride > frames) {
    throw InputError(ctx.param("stride") + ": expected at most the number of frames, got " +
                     std::to_string(s.stride) + held);
  }
  return s;
}

}  // namespace granpipe
