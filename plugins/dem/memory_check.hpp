#pragma once
// Will a scene fit in memory? A run of N spheres holds, at its peak, about
// kBytesPerParticle bytes per sphere (measured as the peak resident size of whole runs:
// the engine's arrays, its neighbour list with histories and reaction slots, the contact
// table of a frame and the frame being written). A scene this machine cannot hold is
// refused before anything is allocated, rather than failing hours later.
#include <string>

namespace granpipe::dem {

inline constexpr double kBytesPerParticle = 1600.0;

// The memory available now (MemAvailable of /proc/meminfo), in bytes; 0 when unknown.
double available_memory();

// Throws InputError starting with `what` (the parameter that sets the count) when
// `particles` spheres need more than the available memory. No check when it is unknown.
void check_memory(const std::string& what, double particles);

}  // namespace granpipe::dem
