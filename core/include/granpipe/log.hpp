#pragma once
#include <fstream>
#include <mutex>
#include <string>

namespace granpipe {

// Messages of a run: to stderr and, once the run has an output directory, to its log.
class Log {
 public:
  void info(const std::string& message);
  void warn(const std::string& message);
  void open_file(const std::string& path);
  void set_quiet(bool quiet) { quiet_ = quiet; }

 private:
  void write(const std::string& line);
  std::mutex mutex_;
  std::ofstream file_;
  bool quiet_ = false;
};

}  // namespace granpipe
