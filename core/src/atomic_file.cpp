#include "granpipe/atomic_file.hpp"

#include <fcntl.h>
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
