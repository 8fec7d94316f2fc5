#pragma once
#include <filesystem>
#include <string>

namespace granpipe {

// Writes `content` to a temporary name beside `path`, flushes, then renames: a reader
// sees the old file or the whole new one, never a part. Throws InputError on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace granpipe
