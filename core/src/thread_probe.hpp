#pragma once
// How many threads this process can run at once. OpenMP's runtime, which plugins use for
// their loops, ends the process (exit 1, "libgomp: Thread creation failed") when it cannot
// start a thread of its team: under an address-space limit, --threads 1024 did. The budget
// handed to the plugins is one the process was seen to hold.

namespace granpipe {

// Starts up to `wanted` - 1 threads beside this one, all alive at once, then releases and
// joins them; returns how many ran, this one included (1 to `wanted`).
int startable_threads(int wanted);

}  // namespace granpipe
