#pragma once
// Connected components of particles joined by edges (contacts, tree edges): union-find
// with path halving and union by size, O(M α(N)) for M edges. Components of two particles
// or more are labelled 0, 1, ... by size (particles) descending, ties by their smallest
// particle, so that the labels do not depend on the order the edges come in; a particle
// without edges is in none.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "granpipe/property_table.hpp"

namespace granpipe {

// Two particle indices.
using ParticlePair = std::pair<std::int64_t, std::int64_t>;

struct ComponentSize {
  std::int64_t particles = 0;
  std::int64_t edges = 0;
};

struct ConnectedComponents {
  IndexArray label;                 // per particle: its component's label, -1 for none
  std::vector<ComponentSize> size;  // by label: size.front() is the largest

  // The largest component's size; zero when there is none.
  ComponentSize largest() const { return size.empty() ? ComponentSize{} : size.front(); }
  // How many components besides the largest, and their edges summed.
  std::int64_t others() const {
    return size.empty() ? 0 : static_cast<std::int64_t>(size.size()) - 1;
  }
  std::int64_t edges_of_others() const;
};

// The components of particles 0..n-1 joined by `edges` (each joins two different
// particles below n; an edge given twice counts twice). Throws InternalError otherwise.
ConnectedComponents connected_components(Eigen::Index n, std::span<const ParticlePair> edges);

}  // namespace granpipe
