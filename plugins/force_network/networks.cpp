#include "networks.hpp"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>
#include <numeric>

namespace granpipe::force_network {

namespace {

// The root of each particle's set after uniting the ends of every contact in `rows`.
IndexArray component_roots(Eigen::Index n, const IndexArray& ci, const IndexArray& cj,
                           const std::vector<Eigen::Index>& rows) {
  IndexArray rank(n), parent(n);
  boost::disjoint_sets<std::int64_t*, std::int64_t*> sets(rank.data(), parent.data());
  for (Eigen::Index p = 0; p < n; ++p) sets.make_set(p);
  for (Eigen::Index row : rows) sets.union_set(ci[row], cj[row]);
  IndexArray root(n);
  for (Eigen::Index p = 0; p < n; ++p) root[p] = sets.find_set(p);
  return root;
}

// Labels the components of two particles or more by size descending, ties by their
// smallest particle (the components come in ascending order of it); -1 for the others.
std::vector<Eigen::Index> network_labels(const std::vector<NetworkSize>& components) {
  std::vector<std::size_t> order(components.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return components[a].particles > components[b].particles;
  });
  std::vector<Eigen::Index> label(components.size(), -1);
  Eigen::Index next = 0;
  for (std::size_t c : order) {
    if (components[c].particles >= 2) label[c] = next++;
  }
  return label;
}

}  // namespace

Networks find_networks(Eigen::Index n, const IndexArray& ci, const IndexArray& cj,
                       const std::vector<Eigen::Index>& rows) {
  const IndexArray root = component_roots(n, ci, cj, rows);
  // The component of each root, numbered as met in ascending particle order.
  IndexArray component_of = IndexArray::Constant(n, -1);
  std::vector<NetworkSize> components;
  for (Eigen::Index p = 0; p < n; ++p) {
    std::int64_t& c = component_of[root[p]];
    if (c < 0) {
      c = static_cast<std::int64_t>(components.size());
      components.emplace_back();
    }
    ++components[static_cast<std::size_t>(c)].particles;
  }
  for (Eigen::Index row : rows) {
    ++components[static_cast<std::size_t>(component_of[root[ci[row]]])].contacts;
  }
  const std::vector<Eigen::Index> label = network_labels(components);
  Networks out;
  out.size.resize(static_cast<std::size_t>(std::count_if(label.begin(), label.end(),
                                                        [](Eigen::Index l) { return l >= 0; })));
  for (std::size_t c = 0; c < components.size(); ++c) {
    if (label[c] >= 0) out.size[static_cast<std::size_t>(label[c])] = components[c];
  }
  out.label.resize(n);
  for (Eigen::Index p = 0; p < n; ++p) {
    out.label[p] = label[static_cast<std::size_t>(component_of[root[p]])];
  }
  return out;
}

}  // namespace granpipe::force_network
