#pragma once
// The initial state of the paper: disks placed at random in the box, without overlap.
#include <string>
#include <vector>

#include "disk_packing.hpp"
#include "granpipe/random.hpp"

namespace granpipe::disks2d_tap {

// Places disks of the given radii one after another, the largest first, at uniformly
// random positions in [0, width] x [0, height], each retrying up to `attempts` times when
// it would overlap one placed before. Throws InputError naming `where` when a disk finds
// no room.
DiskPacking place_at_random(double width, double height, const std::vector<double>& radii,
                            RandomStream& rng, const std::string& where, int attempts = 10000);

}  // namespace granpipe::disks2d_tap
