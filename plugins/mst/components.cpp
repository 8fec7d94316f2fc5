#include "components.hpp"

#include <utility>

namespace granpipe::mst {

Components components(std::uint32_t particles, const std::vector<ParticlePair>& edges) {
  ConnectedComponents found = connected_components(particles, edges);
  const ComponentSize largest = found.largest();
  return {.counts = {.largest_particles = largest.particles,
                     .largest_edges = largest.edges,
                     .others = found.others(),
                     .other_edges = found.edges_of_others()},
          .label = std::move(found.label)};
}

}  // namespace granpipe::mst
