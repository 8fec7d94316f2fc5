#pragma once
// The deepest overlap between two particles of a frame: what a source checks on the
// particles it reads, and an analyzer that models them as (nearly) hard checks before it
// measures, so that interpenetrating spheres are refused rather than turned into numbers.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "granpipe/frame.hpp"

namespace granpipe {

struct PairOverlap {
  Eigen::Index i = 0, j = 0;  // rows in the frame, i < j
  double fraction = 0.0;      // the overlap over the smaller radius
};

// The pair overlapping deepest relative to its smaller radius (of equals, the first in row
// order), or none when no two particles overlap. O(N) with a cell list; throws InputError
// after `where` as find_contacts_by_distance does (a periodic side too short, a box absurdly
// large for the particles).
std::optional<PairOverlap> deepest_pair_overlap(const Frame& frame, const std::string& where);

}  // namespace granpipe
