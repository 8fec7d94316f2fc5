#pragma once
// The counts of the paper's Table II for a graph of particles (the TCPs, the contact
// network): particles and edges of the largest connected component, and how many others
// (of two particles or more) with how many edges in all (granpipe/connected_components.hpp).
#include <cstdint>
#include <vector>

#include "granpipe/connected_components.hpp"

namespace granpipe::mst {

struct TreeCounts {
  std::int64_t largest_particles = 0, largest_edges = 0;
  std::int64_t others = 0, other_edges = 0;
};

struct Components {
  TreeCounts counts;
  // Per particle: its component, 0 the largest, then by particles and first member; -1
  // for a particle without edges.
  IndexArray label;
};

// `edges` pairs of particles below `particles`, each once.
Components components(std::uint32_t particles, const std::vector<ParticlePair>& edges);

}  // namespace granpipe::mst
