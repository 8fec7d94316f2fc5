#pragma once
// How much memory a run may still take: sizes read from input (a scene's spheres, a file's
// declared frames) are checked against it before anything is allocated, rather than failing
// with std::bad_alloc later.

namespace granpipe {

// The memory available now, in bytes: MemAvailable of /proc/meminfo, or less where the
// process's address-space limit or its cgroup's memory limit (less the page cache it may
// drop) leaves less; NaN when none of them is known.
double available_memory();

}  // namespace granpipe
