#pragma once
// The deepest overlap between two particles of a frame: what a source checks on the
// particles it reads, and an analyzer that models them as (nearly) hard checks before it
// measures, so that interpenetrating spheres are refused rather than turned into numbers.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "granpipe/frame.hpp"
#include "granpipe/params.hpp"

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

// Declares max_overlap (real in [0, 1], default `default_value`): the deepest overlap of two
// particles accepted, over the smaller radius; one name and text in every plugin that has it.
void declare_max_overlap(Schema& schema, double default_value, const std::string& what);

// Throws InputError "<where>: particles <id> and <id> overlap by 0.4 of the smaller radius,
// expected at most 0.05 (<param>)<why>" when two particles overlap deeper than max_overlap.
void refuse_deep_overlap(const Frame& frame, double max_overlap, const std::string& param,
                         const std::string& why, const std::string& where);

}  // namespace granpipe
