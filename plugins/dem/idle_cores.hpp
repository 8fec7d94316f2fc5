#pragma once
// Cores that other work leaves idle right now, for the thread governor's first count: beside
// one CPU-bound process on 2 cores, a run of a second or two spent its first quarter second
// on two threads stalling each other before the first probe moved it to one (issue 22).

namespace granpipe::dem {

// The cores this process may run on less the other runnable threads of the machine (the
// fewest of a few samples of /proc/stat's procs_running, this process's own running threads
// counted out), at least 0; the cores it may run on when /proc cannot tell.
int idle_cores();

}  // namespace granpipe::dem
