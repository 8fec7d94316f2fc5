#pragma once
// Connected components of a graph of particles (the TCPs, the contact network) and the
// counts of the paper's Table II: particles and edges of the largest, and how many others
// (of two particles or more) with how many edges in all.
#include <cstdint>
#include <utility>
#include <vector>

#include "granpipe/property_table.hpp"

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
Components components(std::uint32_t particles,
                      const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges);

}  // namespace granpipe::mst
