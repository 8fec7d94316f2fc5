#include "output_directory.hpp"

#include <fstream>

#include "granpipe/errors.hpp"

namespace granpipe {
namespace fs = std::filesystem;

void prepare_output_directory(const fs::path& dir, bool overwrite) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_empty(dir, ec)) {
    if (!overwrite) {
      throw InputError(dir.string() + ": expected a new or empty output directory, got an existing one "
                       "(choose another with --out, or pass --overwrite to replace it)");
    }
    if (!fs::exists(dir / "pipeline.json")) {
      throw InputError(dir.string() + ": --overwrite replaces only granpipe output directories "
                       "(with a pipeline.json), got a directory without one");
    }
    fs::remove_all(dir);
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output directory: " + ec.message());
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << content;
    out.flush();
    if (!out) throw InputError(path.string() + ": expected a writable file, got a write error");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw InputError(path.string() + ": expected a writable file, got " + ec.message());
}

}  // namespace granpipe
