#pragma once
#include <fstream>
#include <mutex>
#include <string>
#include <vector>

namespace granpipe {

// Messages of a run: to stderr (unless quiet) and to the run's log. Every line reaches the
// log: those written before it opens (the plugins' checks run before the output
// directory exists) are kept and written first when it opens; quiet silences the
// terminal only.
class Log {
 public:
  void info(const std::string& message);
  void warn(const std::string& message);
  void open_file(const std::string& path);
  // Ends the run's log: later lines wait for the next open_file.
  void close_file();
  void set_quiet(bool quiet) { quiet_ = quiet; }

 private:
  void write(const std::string& line);
  std::mutex mutex_;
  std::ofstream file_;
  std::vector<std::string> pending_;  // written while no log was open
  bool quiet_ = false;
};

}  // namespace granpipe
