#include "granpipe/atomic_file.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "granpipe/errors.hpp"

namespace granpipe {
namespace fs = std::filesystem;

namespace {

// Writes all of `content` to `fd`; false on the first error.
bool write_all(int fd, const std::string& content) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void write_new_file(const fs::path& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    if (errno == EEXIST) {
      throw InputError(path.string() +
                       ": expected no file at this temporary name, got one (not granpipe's "
                       "now: left as it is)");
    }
    throw InputError(path.string() + ": expected a writable file, got " + std::strerror(errno));
  }
  const bool written = write_all(fd, content);
  if (::close(fd) != 0 || !written) {
    std::error_code ignored;
    fs::remove(path, ignored);  // made just now: ours
    throw InputError(path.string() +
                     ": expected a writable file, got a write error (is the disk full?)");
  }
}

void move_into_place(const fs::path& from, const fs::path& to) {
  if (renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return;
  int why = errno;
  if (why == EINVAL || why == ENOSYS) {
    // A file system without RENAME_NOREPLACE: a hard link fails where `to` exists too; one
    // without hard links either (FUSE mounts) gets a rename where nothing is found.
    if (::link(from.c_str(), to.c_str()) == 0) {
      ::unlink(from.c_str());
      return;
    }
    why = errno;
    std::error_code ec;
    if (why != EEXIST && fs::symlink_status(to, ec).type() == fs::file_type::not_found) {
      if (std::rename(from.c_str(), to.c_str()) == 0) return;
      why = errno;
    }
  }
  if (why == EEXIST) {
    throw InputError(to.string() +
                     ": expected no file of this name (the run writes it at its end), got one "
                     "put there while the run went (not granpipe's: left as it is); the run's "
                     "is " +
                     from.string());
  }
  throw InputError(to.string() + ": expected a writable file, got " + std::strerror(why));
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  const fs::path tmp = path.string() + ".tmp";
  write_new_file(tmp, content);
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);  // ours, and no longer of use
    throw InputError(path.string() + ": expected a writable file, got " + ec.message());
  }
}

}  // namespace granpipe
