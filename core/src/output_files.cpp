#include "granpipe/output_files.hpp"

#include <utility>

#include "granpipe/errors.hpp"

namespace granpipe {

void FileRecord::add(const std::filesystem::path& file) {
  const std::lock_guard<std::mutex> lock(mutex_);
  files_.insert(file.lexically_normal());
}

bool FileRecord::has(const std::filesystem::path& file) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return files_.count(file.lexically_normal()) > 0;
}

OutputFiles::OutputFiles(FileRecord* record, std::filesystem::path dir, std::string name)
    : record_(record), dir_(std::move(dir)), name_(std::move(name)) {}

std::filesystem::path OutputFiles::path(const std::string& suffix) const {
  if (suffix.empty() || (suffix[0] != '.' && suffix[0] != '_') ||
      suffix.find('/') != std::string::npos) {
    throw InternalError(
        "OutputFiles::path: expected a suffix starting with '.' or '_' and "
        "naming no folder, got \"" +
        suffix + "\"");
  }
  // A pipeline only checked makes its plugins without a folder: their names are not used.
  std::filesystem::path file = dir_ / (name_ + suffix);
  if (record_) record_->add(file);
  return file;
}

}  // namespace granpipe
