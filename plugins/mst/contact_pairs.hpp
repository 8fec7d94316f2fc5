#pragma once
// The particle pairs in contact that the TCPs are measured against: from the frame's
// contact table when it has one (particle-particle rows only; by default only those with a
// non-zero normal force, the force network's contacts), otherwise from the centre distance
// (granpipe/contacts_by_distance.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "granpipe/connected_components.hpp"
#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/frame_cache.hpp"

namespace granpipe::mst {

struct ContactPairs {
  using Pair = ParticlePair;
  std::vector<Pair> pairs;  // i < j, sorted, each once
  // For each row of the frame's contact table, its entry in `pairs`, or -1 (a wall, a
  // zero force not counted); empty when the frame has no table.
  std::vector<std::int64_t> pair_of_row;
  std::vector<double> length;  // centre distance of each pair
  bool from_table = false;
  // The frame's loaded pair contacts (granpipe/loaded_pair_contacts.hpp): which frame
  // Table II describes, the one with most. 0 without a contact table.
  std::int64_t loaded = 0;

  // The entry of pair (i, j) in `pairs` (either order), or -1.
  std::int64_t find(std::int64_t i, std::int64_t j) const;
};

struct ContactRule {
  bool zero_force_contacts = false;             // table rows with F_n = 0 count too
  double tolerance = kDefaultContactTolerance;  // relative, for contacts by distance
};

// Throws InputError after `where` for a contact table row that joins a particle to itself
// or has a NaN or infinite normal force.
ContactPairs contact_pairs(const Frame& frame, FrameCache& cache, const ContactRule& rule,
                           const std::string& where);

}  // namespace granpipe::mst
