#include "multipass.hpp"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>
#include <tuple>

namespace granpipe::mst {

Multipass::Multipass(std::uint32_t vertices, std::vector<Edge> edges, double elongation, double tie)
    : vertices_(vertices), elongation_(elongation), tie_(tie), parent_(vertices), rank_(vertices) {
  sorted_.reserve(edges.size());
  for (const Edge& e : edges) sorted_.push_back({e, 0});
  edges = {};
  std::sort(sorted_.begin(), sorted_.end(), ranked_lighter);
}

// Edges first selected by the last pass get longer: they leave the sorted order (in
// order among themselves, since all grow by one factor), and merge back in.
void Multipass::lengthen_last_selection() {
  kept_.clear();
  lengthened_.clear();
  for (const Ranked& r : sorted_) {
    (r.first_pass == static_cast<std::uint32_t>(passes_) ? lengthened_ : kept_).push_back(r);
  }
  for (Ranked& r : lengthened_) r.edge.weight *= elongation_;
  // Rounding may make two weights equal, whose (i, j) order then decides.
  if (!std::is_sorted(lengthened_.begin(), lengthened_.end(), ranked_lighter)) {
    std::sort(lengthened_.begin(), lengthened_.end(), ranked_lighter);
  }
  std::merge(kept_.begin(), kept_.end(), lengthened_.begin(), lengthened_.end(), sorted_.begin(),
             ranked_lighter);
}

// Within `tie` of the run's first weight: chained from one weight to the next, a run of
// 2255 edges spanned 32 ties on a bed moved 1e8 from the origin, taken by (i, j) instead of
// by length, and the forest was not minimal (exit 0).
std::size_t Multipass::tied_run(std::size_t first) {
  std::size_t end = first + 1;
  while (end < sorted_.size() && sorted_[end].edge.weight - sorted_[first].edge.weight <= tie_)
    ++end;
  run_.clear();
  for (std::size_t k = first; k < end; ++k) run_.push_back(&sorted_[k]);
  std::sort(run_.begin(), run_.end(), [](const Ranked* a, const Ranked* b) {
    return std::tie(a->edge.i, a->edge.j) < std::tie(b->edge.i, b->edge.j);
  });
  return end;
}

Multipass::Pass Multipass::next() {
  if (passes_ > 0) lengthen_last_selection();
  ++passes_;
  boost::disjoint_sets<std::uint8_t*, std::uint32_t*> sets(rank_.data(), parent_.data());
  for (std::uint32_t v = 0; v < vertices_; ++v) sets.make_set(v);

  Pass pass;
  // A forest never has more than vertices - 1 edges; after pass 1 its size is known, and
  // the scan stops once it is complete.
  const std::size_t target =
      passes_ == 1 ? std::size_t{vertices_ > 0 ? vertices_ - 1 : 0} : forest_edges_;
  for (std::size_t k = 0; k < sorted_.size() && pass.edges < target;) {
    k = tied_run(k);
    for (Ranked* r : run_) {
      if (pass.edges == target) break;
      const std::uint32_t a = sets.find_set(r->edge.i), b = sets.find_set(r->edge.j);
      if (a == b) continue;
      sets.link(a, b);
      ++pass.edges;
      pass.weight += r->edge.weight;
      if (r->first_pass == 0) {
        r->first_pass = static_cast<std::uint32_t>(passes_);
        pass.new_edges.emplace_back(r->edge.i, r->edge.j);
      }
    }
  }
  if (passes_ == 1) forest_edges_ = pass.edges;
  return pass;
}

}  // namespace granpipe::mst
