#pragma once
#include <filesystem>
#include <string>

namespace granpipe {

// While armed, SIGINT and SIGTERM first record that the run was interrupted (a line in
// run.log, the marker's status, one line on stderr) and then end the process as they
// would have, so its exit status still names the signal. One run per process is
// recorded. Only what is async-signal-safe happens in the handler: everything it
// writes is prepared here.
class InterruptionRecord {
 public:
  // `dir` holds the run's run.log and marker; `marker_text` is the marker to leave;
  // `outcome` ends the stderr line ("out/x is marked interrupted").
  InterruptionRecord(const std::filesystem::path& dir, std::string marker_text, const std::string& outcome);
  ~InterruptionRecord();  // disarms: the signals act as before again
  InterruptionRecord(const InterruptionRecord&) = delete;
  InterruptionRecord& operator=(const InterruptionRecord&) = delete;

 private:
  bool armed_ = false;  // false when another run in this process holds the handlers
};

}  // namespace granpipe
