#pragma once
#include <filesystem>
#include <string>

#include "granpipe/stop_request.hpp"

namespace granpipe {

// While armed, SIGINT and SIGTERM record that the run was interrupted (a line in run.log,
// the marker's status, one line on stderr) and ask the run to stop: it checks
// for it after each frame (plugins in their long loops: stop_request.hpp), unwinds (closing
// frames.partial.h5, so that it opens
// without SWMR) and calls end_by_signal(), which ends the process as the signal would
// have, so its exit status still names it. A second signal acts at once, as before, unless
// it comes within half a second of the first (the same request sent twice, as timeout(1)
// does). One
// run per process is recorded. Only what is async-signal-safe happens in the handler:
// everything it writes is prepared here.
class InterruptionRecord {
 public:
  // `dir` holds the run's run.log and marker; `marker_text` is the marker to leave;
  // `outcome` ends the stderr line ("out/x is marked interrupted").
  InterruptionRecord(const std::filesystem::path& dir, std::string marker_text,
                     const std::string& outcome);
  ~InterruptionRecord();  // disarms: the signals act as before again
  InterruptionRecord(const InterruptionRecord&) = delete;
  InterruptionRecord& operator=(const InterruptionRecord&) = delete;

 private:
  bool armed_ = false;  // false when another run in this process holds the handlers
};

// Ends the process by `signal` as it would have ended without granpipe's handler; returns
// only when the caller's own handler for it returns.
void end_by_signal(int signal);

}  // namespace granpipe
