#pragma once
// The contact that went deepest, relative to the limit of overlap_limit.hpp: looked for
// (O(pairs), outside the hot loop) only once the force loop has reported a contact past
// the limit, to name it.
#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "neighbor_list.hpp"
#include "particles.hpp"
#include "walls.hpp"

namespace granpipe::dem {

struct DeepOverlap {
  std::int32_t tag = -1;    // the particle (its tag, the row in frames)
  std::int32_t other = -1;  // the partner's tag, or -1 for a wall
  Wall wall = Wall::Count;
  double fraction = 0.0;  // overlap over the smaller radius (the particle's, for a wall)
};

// The deepest contact of the listed pairs and of the walls displaced by offset.
DeepOverlap deepest_overlap(const Particles& p, const NeighborList& list, const WallSet& walls,
                            const Eigen::Vector3d& offset);

// "particles 3 and 7 overlap by 62 % of the smaller radius (a run stops past 30 %)", or
// "particle 3 overlaps wall z_low by ... of its radius ...".
std::string describe(const DeepOverlap& d);

}  // namespace granpipe::dem
