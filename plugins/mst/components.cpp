#include "components.hpp"

namespace granpipe::mst {

Components components(std::uint32_t particles, const std::vector<ParticlePair>& edges) {
  ConnectedComponents found = connected_components(particles, edges);
  Components c;
  c.label = std::move(found.label);
  for (std::size_t k = 0; k < found.size.size(); ++k) {
    const ComponentSize& size = found.size[k];
    if (k == 0) {
      c.counts.largest_particles = size.particles;
      c.counts.largest_edges = size.edges;
    } else {
      ++c.counts.others;
      c.counts.other_edges += size.edges;
    }
  }
  return c;
}

}  // namespace granpipe::mst
