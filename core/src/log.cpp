#include "granpipe/log.hpp"

#include <iostream>

namespace granpipe {

void Log::open_file(const std::string& path, const std::string& first) {
  std::lock_guard lock(mutex_);
  // A Log used for several runs writes each run's lines into that run's log only.
  if (file_.is_open()) file_.close();
  file_.clear();
  file_.open(path, std::ios::app);
  if (!first.empty()) {
    if (!quiet_) std::cerr << first << '\n';
    file_ << first << '\n';
  }
  for (const std::string& line : pending_) file_ << line << '\n';
  file_ << std::flush;
  pending_.clear();
}

void Log::close_file() {
  std::lock_guard lock(mutex_);
  file_.close();
}

void Log::info(const std::string& message) {
  if (parent_) return parent_->info(prefix_ + message);
  write(message);
}

void Log::warn(const std::string& message) {
  if (parent_) return parent_->warn(prefix_ + message);
  write("warning: " + message);
}

void FirstFrameWarning::warn(Log& log, const std::string& message) {
  if (said_) return;
  said_ = true;
  log.warn(message + "; said for the first such frame only");
}

void Log::write(const std::string& line) {
  std::lock_guard lock(mutex_);
  if (!quiet_) std::cerr << line << '\n';
  if (file_.is_open()) {
    file_ << line << '\n' << std::flush;
  } else {
    pending_.push_back(line);
  }
}

}  // namespace granpipe
