#pragma once
// Bernal's canonical holes (the tapping paper's Table I): the pore size xi = r/R of each
// regular hole and its share, in number and in volume, in Bernal's ball model.
#include <array>
#include <cstddef>

namespace granpipe::pores {

struct BernalHole {
  const char* name;
  double xi;              // r/R of the regular hole
  double number_percent;  // Table I
  double volume_percent;  // Table I
};

// By increasing xi.
const std::array<BernalHole, 5>& bernal_holes();

// The hole whose xi is nearest, when xi is within half the gap to the neighbouring hole
// (on the outer sides, half the gap to the one neighbour); bernal_holes().size() for
// none. Real holes are distorted: xi of a regular hole is where its pores gather.
std::size_t nearest_hole(double xi);

}  // namespace granpipe::pores
