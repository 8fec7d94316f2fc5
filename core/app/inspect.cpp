#include <iostream>

#include "commands.hpp"
#include "granpipe/frame_store.hpp"

namespace granpipe::app {

void inspect(const std::string& path, long max_rows) {
  FrameReader reader(path);
  const FrameFileInfo& info = reader.info();
  std::cout << info.path << ": " << info.frames << " frame(s), N = " << info.particles
            << ", dim = " << info.dim << ", particles group \"" << info.group << "\""
            << (info.complete ? "" : ", INCOMPLETE (the writer did not finish)") << "\n"
            << "written by: " << (info.creator.empty() ? "unknown" : info.creator)
            << (info.granpipe_file ? " (granpipe layout)" : " (plain H5MD)") << "\n"
            << "each frame holds: position" << (info.has_radius ? ", radius" : "")
            << (info.has_velocity ? ", velocity" : "")
            << (info.has_angular_velocity ? ", angular velocity" : "")
            << (info.has_supports ? ", support labels" : "") << (info.has_contacts ? ", contacts" : "")
            << "\n";
  std::cout << "frame      step          time    tap  cycle  contacts\n";
  const long rows = std::min(info.frames, max_rows);
  for (long k = 0; k < rows; ++k) {
    const Frame f = reader.read(k);
    std::printf("%5ld %9lld %13.6g %6lld %6lld %9lld\n", k, static_cast<long long>(f.step), f.time,
                static_cast<long long>(f.tap), static_cast<long long>(f.cycle),
                static_cast<long long>(f.contacts ? f.contacts->size() : 0));
  }
  if (rows < info.frames) std::cout << "... (" << info.frames - rows << " more; --rows N shows more)\n";
}

}  // namespace granpipe::app
