#pragma once
#include <filesystem>
#include <optional>

namespace granpipe {

// An exclusive advisory lock (flock) on a directory, held from try_lock() until the
// object dies or the process ends, however it ends. The lock follows the directory
// through renames, so a run keeps it while its new directory is swapped into place.
class DirectoryLock {
 public:
  // The lock, or nothing when another process (or another lock here) holds it.
  // Throws InputError when the directory cannot be opened.
  static std::optional<DirectoryLock> try_lock(const std::filesystem::path& dir);
  ~DirectoryLock();
  DirectoryLock(DirectoryLock&& other) noexcept;
  DirectoryLock& operator=(DirectoryLock&& other) noexcept;
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  explicit DirectoryLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace granpipe
