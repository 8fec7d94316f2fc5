#pragma once
#include <fstream>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace granpipe {

// Messages of a run: to stderr (unless quiet) and to the run's log. Every line reaches the
// log: those written before it opens (the plugins' checks run before the output
// directory exists) are kept and written first when it opens; quiet silences the
// terminal only.
class Log {
 public:
  Log() = default;
  // A log whose lines go to `parent` after `prefix`: a sweep point's plugins say which point
  // they speak of ("point 3: "), where the lines of all points came interleaved and alike.
  Log(Log& parent, std::string prefix) : parent_(&parent), prefix_(std::move(prefix)) {}
  Log(const Log&) = delete;
  Log& operator=(const Log&) = delete;

  void info(const std::string& message);
  void warn(const std::string& message);
  // `first`, when given, is the log's first line, before those kept until it opened (the
  // run's provenance line came after the plugins' early warnings); said as info() says it.
  void open_file(const std::string& path, const std::string& first = "");
  // Ends the run's log: later lines wait for the next open_file.
  void close_file();
  void set_quiet(bool quiet) { quiet_ = quiet; }

 private:
  void write(const std::string& line);
  std::mutex mutex_;
  std::ofstream file_;
  std::vector<std::string> pending_;  // written while no log was open
  bool quiet_ = false;
  Log* parent_ = nullptr;
  std::string prefix_;
};

// A warning an analyzer would otherwise repeat for every frame of a long run (a value
// undefined in each): said for the first frame it concerns only, and says so.
class FirstFrameWarning {
 public:
  // Whether it is still to be said: build the message only then.
  bool pending() const { return !said_; }
  // Warns "<message>; said for the first such frame only", the first time.
  void warn(Log& log, const std::string& message);

 private:
  bool said_ = false;
};

}  // namespace granpipe
