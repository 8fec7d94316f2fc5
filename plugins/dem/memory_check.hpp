#pragma once
// Will a scene fit in memory? A run holds, at its peak, the engine's arrays, its neighbour
// list with histories and reaction slots, and a frame with its contact table being
// written. Measured as the peak resident size of whole runs (frames with contacts saved,
// one thread): 0.81 kB per sphere on loose lattices of 2e5, 8e5 and
// 5e6 spheres (4.1 GB), which list 2 neighbours per sphere, and 2.4 kB per sphere on the
// settled 7601 of data-samples/bnp_settled.h5, which list 6 to 7 but whose small size
// leaves the files' fixed buffers in the figure. A settled bed's extra neighbours cost about
// 150 bytes each with their contact rows, so 2 kB per sphere is taken. A scene this machine
// cannot hold is refused before anything is allocated, rather than failing with
// std::bad_alloc hours later.
#include <string>

namespace granpipe::dem {

inline constexpr double kBytesPerParticle = 2000.0;

// Throws InputError starting with `what` (the parameter that sets the count) when
// `particles` spheres need more than the available memory. No check when it is unknown.
void check_memory(const std::string& what, double particles);

}  // namespace granpipe::dem
