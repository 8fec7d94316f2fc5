#include "granpipe/start_frame.hpp"

#include "granpipe/errors.hpp"
#include "granpipe/frame_store.hpp"

namespace granpipe {

std::optional<StartFrame> read_start_frame(const PluginContext& ctx, double default_radius) {
  const std::string file = ctx.params.string("initial_file");
  const long wanted = ctx.params.integer("initial_frame");
  if (file.empty()) {
    if (wanted == -1) return std::nullopt;
    throw InputError(ctx.param("initial_frame") +
                     ": expected it only with initial_file (a frame of that file), got " +
                     std::to_string(wanted) + " without one");
  }
  // The reader's refusals (not HDF5, not H5MD, corrupt) name the file; the parameter too.
  const FrameReader reader = [&] {
    try {
      return FrameReader(file, "", default_radius);
    } catch (const InputError& e) {
      throw InputError(ctx.param("initial_file") + ": " + e.what());
    }
  }();
  const long frames = reader.frames();
  if (frames == 0)
    throw InputError(ctx.param("initial_file") + ": " + file +
                     ": expected a file with frames, got none");
  if (wanted >= frames) {
    throw InputError(ctx.param("initial_frame") + ": expected -1 or a frame index below " +
                     std::to_string(frames) + " (" + file + " holds " + std::to_string(frames) +
                     " frames), got " + std::to_string(wanted));
  }
  const long index = wanted < 0 ? frames - 1 : wanted;
  return StartFrame{reader.read(index), index,
                    ctx.param("initial_file") + ": " + file + ": frame " + std::to_string(index),
                    reader.info().has("radius"), reader.info().has("species")};
}

}  // namespace granpipe
