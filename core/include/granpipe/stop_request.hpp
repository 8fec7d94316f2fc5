#pragma once
// A SIGINT or SIGTERM asks a run to stop: the runner looks after each frame, and a plugin
// whose one frame may take minutes (a tap of a wide bed, many DEM steps between saves)
// looks in its loops too, so that the signal is not left waiting for the frame's end.
// Call throw_if_stop_requested() only where an exception may leave: never inside an
// OpenMP region.

namespace granpipe {

// What is thrown to unwind once a signal asked the run to stop; not an std::exception, so
// that no handler for errors takes it for a failure. The runner catches it, closes the
// files whole and marks the run interrupted.
struct StopRequested {
  int signal;
};

// Throws StopRequested when a signal asked the run to stop.
void throw_if_stop_requested();

}  // namespace granpipe
