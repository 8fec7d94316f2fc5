#pragma once
// Connected components of particles linked by a set of contacts (Boost.Graph's disjoint
// sets, incremental: O(M α(N)) for M contacts). A network is a component of two particles
// or more; a particle linked to none is in no network.
#include <vector>

#include "granpipe/frame.hpp"

namespace granpipe::force_network {

struct NetworkSize {
  long particles = 0;
  long contacts = 0;
};

struct Networks {
  // Per particle: its network's label, -1 for a particle in no network. Labels are 0, 1,
  // ... by size (particles) descending, ties by the smallest particle index: label 0 is
  // the largest network, whatever order the contacts came in.
  IndexArray label;
  std::vector<NetworkSize> size;  // by label
};

// The networks of the n particles linked by the contacts in `rows` (rows of contact_i /
// contact_j naming two particles).
Networks find_networks(Eigen::Index n, const IndexArray& contact_i, const IndexArray& contact_j,
                       const std::vector<Eigen::Index>& rows);

}  // namespace granpipe::force_network
