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

// Renames `from` (a file the run wrote under a temporary name) to `to`, which must not
// exist: a file put at `to` while the run went (a user's results.h5) was renamed over.
// InputError naming both when it exists, leaving it and `from` as they are.
void move_into_place(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace granpipe
