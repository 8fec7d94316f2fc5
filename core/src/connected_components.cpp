#include "granpipe/connected_components.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "granpipe/errors.hpp"

namespace granpipe {

namespace {

class DisjointSets {
 public:
  explicit DisjointSets(Eigen::Index n)
      : parent_(static_cast<std::size_t>(n)), size_(parent_.size(), 1) {
    std::iota(parent_.begin(), parent_.end(), std::int64_t{0});
  }

  std::int64_t root(std::int64_t p) {
    while (at(parent_, p) != p) {
      at(parent_, p) = at(parent_, at(parent_, p));
      p = at(parent_, p);
    }
    return p;
  }

  void unite(std::int64_t a, std::int64_t b) {
    a = root(a);
    b = root(b);
    if (a == b) return;
    if (at(size_, a) < at(size_, b)) std::swap(a, b);
    at(parent_, b) = a;
    at(size_, a) += at(size_, b);
  }

 private:
  static std::int64_t& at(std::vector<std::int64_t>& v, std::int64_t k) {
    return v[static_cast<std::size_t>(k)];
  }
  std::vector<std::int64_t> parent_, size_;
};

void check_edge(Eigen::Index n, const ParticlePair& e) {
  const auto [i, j] = e;
  if (i < 0 || j < 0 || i >= n || j >= n || i == j) {
    throw InternalError(
        "connected_components: expected an edge between two different "
        "particles below " +
        std::to_string(n) + ", got " + std::to_string(i) + " and " + std::to_string(j));
  }
}

// Labels of the components (numbered in ascending order of their smallest particle) by
// size descending; the stable sort keeps that order among equals.
std::vector<std::int64_t> labels_by_size(const std::vector<ComponentSize>& found) {
  std::vector<std::size_t> order(found.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return found[a].particles > found[b].particles;
  });
  std::vector<std::int64_t> label(found.size());
  for (std::size_t k = 0; k < order.size(); ++k) label[order[k]] = static_cast<std::int64_t>(k);
  return label;
}

}  // namespace

std::int64_t ConnectedComponents::edges_of_others() const {
  std::int64_t edges = 0;
  for (std::size_t k = 1; k < size.size(); ++k) edges += size[k].edges;
  return edges;
}

ConnectedComponents connected_components(Eigen::Index n, std::span<const ParticlePair> edges) {
  DisjointSets sets(n);
  std::vector<bool> linked(static_cast<std::size_t>(n), false);
  for (const ParticlePair& e : edges) {
    check_edge(n, e);
    sets.unite(e.first, e.second);
    linked[static_cast<std::size_t>(e.first)] = linked[static_cast<std::size_t>(e.second)] = true;
  }
  // The component of each root, numbered as met in ascending particle order.
  IndexArray found_of_root = IndexArray::Constant(n, -1);
  std::vector<ComponentSize> found;
  for (Eigen::Index p = 0; p < n; ++p) {
    if (!linked[static_cast<std::size_t>(p)]) continue;
    std::int64_t& c = found_of_root[sets.root(p)];
    if (c < 0) {
      c = static_cast<std::int64_t>(found.size());
      found.emplace_back();
    }
    ++found[static_cast<std::size_t>(c)].particles;
  }
  for (const ParticlePair& e : edges) {
    ++found[static_cast<std::size_t>(found_of_root[sets.root(e.first)])].edges;
  }

  const std::vector<std::int64_t> label = labels_by_size(found);
  ConnectedComponents out;
  out.size.resize(found.size());
  for (std::size_t c = 0; c < found.size(); ++c)
    out.size[static_cast<std::size_t>(label[c])] = found[c];
  out.label = IndexArray::Constant(n, -1);
  for (Eigen::Index p = 0; p < n; ++p) {
    const std::int64_t c = found_of_root[sets.root(p)];
    if (c >= 0) out.label[p] = label[static_cast<std::size_t>(c)];
  }
  return out;
}

}  // namespace granpipe
