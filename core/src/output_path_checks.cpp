#include "output_path_checks.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "granpipe/errors.hpp"
#include "output_directory.hpp"

namespace granpipe {
namespace fs = std::filesystem;

namespace {

std::string describe_kind(fs::file_type type) {
  switch (type) {
    case fs::file_type::regular:
      return "a regular file";
    case fs::file_type::symlink:
      return "a symlink";
    case fs::file_type::fifo:
      return "a named pipe";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::block:
    case fs::file_type::character:
      return "a device file";
    default:
      return "a special file";
  }
}

// Absolute, with every symlink resolved (as far as the path exists), or empty.
fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::path() : r;
}

// True when `outer` is `inner` or one of its ancestors (both resolved).
bool holds(const fs::path& outer, const fs::path& inner) {
  auto i = inner.begin();
  for (const fs::path& part : outer) {
    if (part.empty()) continue;
    if (i == inner.end() || *i != part) return false;
    ++i;
  }
  return true;
}

fs::path home_directory() {
  if (const char* home = std::getenv("HOME"); home && *home) return home;
  if (const passwd* pw = getpwuid(getuid()); pw && pw->pw_dir) return pw->pw_dir;
  return {};
}

// The kernel's own word where it gives it (a bind mount of the same file system counts, a
// btrfs subvolume, renamed like a folder, does not); else another device than the parent's.
bool is_mount_point(const fs::path& dir, const struct stat& folder, const struct stat& parent) {
  struct statx x {};
  if (statx(AT_FDCWD, dir.c_str(), AT_SYMLINK_NOFOLLOW, STATX_BASIC_STATS, &x) == 0 &&
      (x.stx_attributes_mask & STATX_ATTR_MOUNT_ROOT))
    return (x.stx_attributes & STATX_ATTR_MOUNT_ROOT) != 0;
  return folder.st_dev != parent.st_dev;
}

}  // namespace

fs::path without_trailing_separators(const fs::path& dir) {
  std::string s = dir.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

void check_output_spelling(const fs::path& dir) {
  bool past_start = false;
  fs::path previous;
  for (const fs::path& part : dir) {
    const bool dots = part == "." || part == "..";
    if (dots && past_start) {
      throw InputError(dir.string() + ": expected an output directory without . or .. after " +
                       "its first named folder, got \"" + part.string() + "\" after \"" +
                       previous.string() + "\"; write the folder it means (a run into out/x/. " +
                       "would be swapped into itself, and out/missing/.. made missing/)");
    }
    past_start = past_start || !dots;
    previous = part;
  }
}

void check_output_kind(const fs::path& dir) {
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(dir, ec);
  if (st.type() == fs::file_type::not_found) return;
  if (ec) throw InputError(dir.string() + ": cannot read what it is: " + ec.message());
  if (fs::is_symlink(st)) {
    throw InputError(dir.string() + ": expected a directory, got a symlink (to " +
                     fs::read_symlink(dir, ec).string() + "); give the directory itself as --out");
  }
  if (!fs::is_directory(st))
    throw InputError(dir.string() + ": expected a directory, got " + describe_kind(st.type()));
}

void check_output_place(const fs::path& dir, const std::vector<InputFile>& inputs) {
  const fs::path out = resolved(dir);
  if (out.empty()) throw InputError(dir.string() + ": cannot resolve the output directory's path");
  std::error_code ec;
  const std::pair<fs::path, const char*> places[] = {
      {out.root_path(), "the root directory"},
      {resolved(fs::current_path(ec)), "the working directory"},
      {resolved(home_directory()), "the home directory"}};
  for (const auto& [place, name] : places) {
    if (place.empty() || !holds(out, place)) continue;
    throw InputError(dir.string() + ": expected a directory of the run's own, got " + out.string() +
                     ", which " + (out == place ? "is " : "holds ") + name +
                     "; choose another --out");
  }
  for (const InputFile& input : inputs) {
    const fs::path file = resolved(input.file);
    if (file.empty() || !holds(out, file)) continue;
    throw InputError(input.where + ": expected a file outside the output directory " +
                     dir.string() + ", got \"" + input.file.string() +
                     "\" inside it; granpipe never writes where it reads (choose another --out)");
  }
}

void check_removable(const fs::path& dir) {
  auto refuse = [&](const fs::path& where, const std::string& why) {
    throw InputError(where.string() + ": --overwrite would have to remove the earlier run in " +
                     dir.string() + " but cannot (" + why + "); nothing was changed");
  };
  if (access(dir.parent_path().empty() ? "." : dir.parent_path().c_str(), W_OK | X_OK) != 0)
    refuse(dir.parent_path(), std::strerror(errno));
  if (access(dir.c_str(), W_OK | X_OK) != 0) refuse(dir, std::strerror(errno));
  // What access() does not see, and the swap at the end of the run then failed on, its
  // results left aside: a mount point cannot be renamed, and in a sticky folder (/tmp)
  // only the owner of an entry, or of the folder, may rename it.
  struct stat folder {
  }, parent{};
  const fs::path above = dir.parent_path().empty() ? fs::path(".") : dir.parent_path();
  if (stat(dir.c_str(), &folder) == 0 && stat(above.c_str(), &parent) == 0) {
    if (is_mount_point(dir, folder, parent))
      refuse(dir, "it is a mount point, which cannot be renamed");
    const uid_t me = geteuid();
    if ((parent.st_mode & S_ISVTX) && me != 0 && folder.st_uid != me && parent.st_uid != me)
      refuse(dir, "another user owns it, in a folder where only owners may rename");
  }
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code kind;
    const bool folder = it->symlink_status(kind).type() == fs::file_type::directory;
    if (folder && access(it->path().c_str(), W_OK | X_OK) != 0)
      refuse(it->path(), std::strerror(errno));
  }
  if (ec) refuse(dir, ec.message());
}

}  // namespace granpipe
