#pragma once
// Contacts found from geometry alone, for frames whose source reports none (hard
// particles, lattices, other codes' files). Two particles touch when their centre
// distance is at most (R_i + R_j)(1 + tolerance); a particle touches a wall when its
// centre is within R_i (1 + tolerance) of it. The tolerance is relative to particle size,
// so that exactly touching particles (lattices, deposits) count whatever their size.
#include <string>

#include "granpipe/frame.hpp"
#include "granpipe/frame_cache.hpp"
#include "granpipe/params.hpp"

namespace granpipe {

constexpr double kDefaultContactTolerance = 1e-9;
constexpr const char* kContactToleranceName = "contact_tolerance";

// Declares the parameter contact_tolerance (real >= 0, default kDefaultContactTolerance) of
// a plugin that finds contacts by distance: one name and one text in every such plugin.
void declare_contact_tolerance(Schema& schema);

struct DistanceContacts {
  double tolerance = 0.0;
  // Particle pairs (i < j, sorted) first, then particle-wall contacts (j = partner::wall(w),
  // sorted by particle).
  IndexArray i, j;
  // Surface separation: |r_ij| - R_i - R_j, or the centre-wall distance - R_i; negative
  // when the particles overlap.
  Eigen::ArrayXd gap;
  Eigen::Index pairs = 0;  // how many of the entries are particle pairs

  Eigen::Index size() const { return i.size(); }
  Eigen::Index wall_contacts() const { return size() - pairs; }
  // Contacts of each of n particles, counting the walls or not.
  IntArray coordination(Eigen::Index n, bool with_walls) const;
};

// O(N) with a cell list. Throws InputError when a periodic side is shorter than twice
// the largest contact distance (a pair would touch through two images), or the box is
// absurdly large for the particles (see CellList); the message starts with `where`
// ("frame at step S" if not given).
DistanceContacts find_contacts_by_distance(const Frame& frame, double tolerance,
                                           const std::string& where);
DistanceContacts find_contacts_by_distance(const Frame& frame, double tolerance);

// "" when the frame's positions are known finely enough for contacts at this tolerance;
// else why not, to follow the analyzer's name and the frame's in a warning: far from the
// origin a coordinate is rounded to more than the tolerance allows, and touching particles
// are missed (an FCC lattice moved to 1e7 had z 9 for 12, without a word).
std::string coarse_for_contacts(const Frame& frame, double tolerance);

// The FrameCache key of the contacts for this tolerance.
std::string contacts_by_distance_key(double tolerance);

// The frame's contacts for this tolerance, computed once per frame and shared through
// the cache by every analyzer that asks with the same tolerance.
const DistanceContacts& contacts_by_distance(const Frame& frame, FrameCache& cache,
                                             double tolerance);

}  // namespace granpipe
