// libFuzzer target: the input bytes as an H5MD file, opened with FrameReader and its
// frames read and checked as the h5md source does. Anything but an InputError escaping
// is a finding (docs/fuzzing.md).
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "granpipe/errors.hpp"
#include "granpipe/frame_store.hpp"

namespace {

// Frames read: the first ones and the last. A file of a few bytes may hold millions of
// frames without particles, which would take minutes to read one by one.
constexpr long kFirstFrames = 100;

// A file of this process's own, rewritten for every input (HDF5 reads files by name).
const std::filesystem::path& input_file() {
  static const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                            ("granpipe_fuzz_" + std::to_string(getpid()) + ".h5");
  return path;
}

void read_checked(const granpipe::FrameReader& reader, long k) {
  reader.read(k).check(input_file().string() + ": frame " + std::to_string(k));
}

}  // namespace

// As in a normal build, an absurd allocation fails instead of stopping the process: HDF5
// meets the sizes of a damaged file with a failed malloc and an error, which granpipe turns
// into an InputError; an allocation of granpipe's own throws std::bad_alloc, a finding.
// HDF5 1.10 leaks a few bytes on some damaged object headers: not granpipe's to find.
extern "C" const char* __asan_default_options() {
  return "allocator_may_return_null=1:detect_leaks=0";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(input_file(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const granpipe::FrameReader reader(input_file());
    const long frames = reader.frames();
    for (long k = 0; k < std::min(frames, kFirstFrames); ++k) read_checked(reader, k);
    if (frames > kFirstFrames) read_checked(reader, frames - 1);
  } catch (const granpipe::InputError&) {
    // Bad input, reported as it should be.
  }
  std::filesystem::remove(input_file());
  return 0;
}
