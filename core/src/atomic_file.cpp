#include "granpipe/atomic_file.hpp"

#include <fstream>

#include "granpipe/errors.hpp"

namespace granpipe {
namespace fs = std::filesystem;

void write_file_atomically(const fs::path& path, const std::string& content) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << content;
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(tmp, ignored);
      throw InputError(path.string() +
                       ": expected a writable file, got a write error (is the disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);  // ours, and no longer of use
    throw InputError(path.string() + ": expected a writable file, got " + ec.message());
  }
}

}  // namespace granpipe
