#include "granpipe/file_kind.hpp"

#include <system_error>

namespace granpipe {

namespace fs = std::filesystem;

std::string what_is_at(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec == std::errc::too_many_symbolic_link_levels) return "a loop of symbolic links";
  if (ec == std::errc::permission_denied) return "a path that cannot be searched (permissions)";
  switch (status.type()) {
    case fs::file_type::regular:
      return "a regular file";
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::not_found:
    case fs::file_type::none: {
      std::error_code link_ec;
      if (fs::symlink_status(path, link_ec).type() == fs::file_type::symlink) {
        return "a symbolic link to nothing (" + fs::read_symlink(path, link_ec).string() + ")";
      }
      return "no such file";
    }
    default:
      return "no regular file (a pipe, socket or device)";
  }
}

bool regular_file_at(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

bool anything_at(const fs::path& path) {
  std::error_code ec;
  return fs::symlink_status(path, ec).type() != fs::file_type::not_found && !ec;
}

}  // namespace granpipe
