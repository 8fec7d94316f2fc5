#include "components.hpp"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>
#include <tuple>

namespace granpipe::mst {

namespace {

struct Component {
  std::int64_t particles = 0, edges = 0;
  std::uint32_t first = 0;  // lowest particle
  // More particles first; ties by the first particle, so that components of the same
  // particles get the same label whatever their edges.
  bool before(const Component& o) const {
    return std::tie(o.particles, first) < std::tie(particles, o.first);
  }
};

}  // namespace

Components components(std::uint32_t particles,
                      const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
  std::vector<std::uint32_t> parent(particles);
  std::vector<std::uint8_t> rank(particles);
  boost::disjoint_sets<std::uint8_t*, std::uint32_t*> sets(rank.data(), parent.data());
  for (std::uint32_t v = 0; v < particles; ++v) sets.make_set(v);
  for (const auto& [i, j] : edges) sets.union_set(i, j);

  // One entry per root with an edge, in order of the roots' first particle.
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> slot_of_root(particles, kNone);
  std::vector<Component> found;
  std::vector<bool> linked(particles, false);
  for (const auto& [i, j] : edges) linked[i] = linked[j] = true;
  auto slot = [&](std::uint32_t v) -> std::size_t& { return slot_of_root[sets.find_set(v)]; };
  for (std::uint32_t v = 0; v < particles; ++v) {
    if (!linked[v]) continue;
    if (slot(v) == kNone) {
      slot(v) = found.size();
      found.push_back({0, 0, v});
    }
    ++found[slot(v)].particles;
  }
  for (const auto& [i, j] : edges) ++found[slot(i)].edges;

  std::vector<std::size_t> order(found.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return found[a].before(found[b]); });
  std::vector<std::int64_t> label_of(found.size());
  for (std::size_t k = 0; k < order.size(); ++k) label_of[order[k]] = static_cast<std::int64_t>(k);

  Components c;
  c.label = IndexArray::Constant(particles, -1);
  for (std::uint32_t v = 0; v < particles; ++v) {
    if (linked[v]) c.label[v] = label_of[slot(v)];
  }
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Component& comp = found[order[k]];
    if (k == 0) {
      c.counts.largest_particles = comp.particles;
      c.counts.largest_edges = comp.edges;
    } else {
      ++c.counts.others;
      c.counts.other_edges += comp.edges;
    }
  }
  return c;
}

}  // namespace granpipe::mst
