#include "merge_cells.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>

#include "granpipe/connected_components.hpp"
#include "granpipe/parallel_errors.hpp"

namespace granpipe::pores {

namespace {

// Cells of one pore are those whose circumspheres agree within `length` (tolerance R),
// widened by what their rounded corners leave undetermined (DelaunayCell::uncertainty): a
// site ringed by thousands of cospherical spheres has cells so thin that their centres,
// even computed exactly from the rounded coordinates, scatter 1e-7 R. The widening stops
// at `widest` (a thousandth of R): the cells of the hull, or of a flat bottom layer, are
// known to no better than R and would join pores far apart.
struct SameSphere {
  const std::vector<DelaunayCell>& cells;
  double length;
  double widest;
  std::vector<ParticlePair> pairs;

  bool pore(std::uint32_t i) const { return i != kHull && cells[i].pore && !cells[i].flat; }
  bool same_sphere(const DelaunayCell& a, const DelaunayCell& b) const {
    const double within = length + std::min(double{a.uncertainty} + double{b.uncertainty}, widest);
    return std::abs(a.radius - b.radius) <= within &&
           (a.centre - b.centre).squaredNorm() <= within * within;
  }
  void compare(std::uint32_t i, std::uint32_t j) {
    if (pore(i) && pore(j) && same_sphere(cells[i], cells[j]))
      pairs.emplace_back(std::int64_t{i}, std::int64_t{j});
  }
  // Cell i with its neighbours after it, or a flat cell's neighbours with each other.
  void compare_around(std::uint32_t i) {
    const auto& n = cells[i].neighbours;
    if (!cells[i].flat) {
      for (std::uint32_t j : n)
        if (j != kHull && j > i) compare(i, j);
      return;
    }
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) compare(n[a], n[b]);
  }
};

// The neighbours of a cell some cells ahead, fetched into the cache before their
// comparison: they lie anywhere in the cells' array.
constexpr std::size_t kPrefetchAhead = 8;

void prefetch_neighbours(const std::vector<DelaunayCell>& cells, std::size_t i) {
  for (std::uint32_t n : cells[i].neighbours)
    if (n != kHull) __builtin_prefetch(&cells[n]);
}

// The pairs of cells of one sphere, each thread comparing a run of cells: concatenated in
// the runs' order, they come in the cells' order whatever the threads.
std::vector<ParticlePair> same_sphere_pairs(const SameSphere& rule, int threads) {
  const std::vector<DelaunayCell>& cells = rule.cells;
  std::vector<std::vector<ParticlePair>> runs(static_cast<std::size_t>(threads));
  ParallelErrors errors;
#pragma omp parallel num_threads(threads)
  errors.run([&] {
    const auto part = static_cast<std::size_t>(omp_get_thread_num());
    const auto parts = static_cast<std::size_t>(omp_get_num_threads());
    SameSphere same{cells, rule.length, rule.widest, {}};
    for (std::size_t i = cells.size() * part / parts; i < cells.size() * (part + 1) / parts; ++i) {
      if (i + kPrefetchAhead < cells.size()) prefetch_neighbours(cells, i + kPrefetchAhead);
      same.compare_around(static_cast<std::uint32_t>(i));
    }
    runs[part] = std::move(same.pairs);
  });
  errors.rethrow();
  std::vector<ParticlePair> pairs;
  for (const auto& run : runs) pairs.insert(pairs.end(), run.begin(), run.end());
  return pairs;
}

}  // namespace

MergedPores merge_cells(const std::vector<DelaunayCell>& cells, double radius, double tolerance,
                        int threads) {
  const SameSphere same{cells, tolerance * radius, 1e-3 * radius, {}};
  // The groups among the cells of some pair alone (a random packing has few), numbered
  // in the cells' order, so that the labels are those of all cells.
  std::vector<ParticlePair> pairs = same_sphere_pairs(same, threads);
  std::vector<std::int64_t> paired;
  for (const auto& [i, j] : pairs) paired.insert(paired.end(), {i, j});
  std::sort(paired.begin(), paired.end());
  paired.erase(std::unique(paired.begin(), paired.end()), paired.end());
  const auto place = [&](std::int64_t i) {
    return std::lower_bound(paired.begin(), paired.end(), i) - paired.begin();
  };
  for (auto& [i, j] : pairs) std::tie(i, j) = std::pair(place(i), place(j));
  const ConnectedComponents groups =
      connected_components(static_cast<Eigen::Index>(paired.size()), pairs);
  MergedPores merged;
  // Groups first (labels 0, 1, ...), then every cell that shares its sphere with none.
  merged.pores.resize(groups.size.size());
  merged.pores.reserve(cells.size());
  auto next_paired = paired.begin();
  for (std::uint32_t i = 0; i < cells.size(); ++i) {
    merged.flat_cells += cells[i].flat ? 1 : 0;
    const bool in_pair = next_paired != paired.end() && *next_paired == i;
    const std::int64_t label = in_pair ? groups.label[next_paired++ - paired.begin()] : -1;
    if (!same.pore(i)) continue;
    Pore& pore =
        label >= 0 ? merged.pores[static_cast<std::size_t>(label)] : merged.pores.emplace_back();
    pore.centre += cells[i].centre;
    pore.radius += cells[i].radius;
    ++pore.cells;
  }
  for (Pore& p : merged.pores) {
    p.centre /= p.cells;
    p.radius /= p.cells;
  }
  return merged;
}

}  // namespace granpipe::pores
