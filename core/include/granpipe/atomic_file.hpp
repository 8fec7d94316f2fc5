#pragma once
#include <filesystem>
#include <string>

namespace granpipe {

// Writes `content` to a temporary name beside `path`, flushes, then renames: a reader
// sees the old file or the whole new one, never a part. Throws InputError on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// Writes `content` to a file it creates at `path`, refusing (InputError) anything already
// there, a symlink included: a symlink planted at a temporary name had a run's write land
// on the file it pointed to, outside the run's folder. Removes what it made on failure.
void write_new_file(const std::filesystem::path& path, const std::string& content);

}  // namespace granpipe
