#include "cell_order.hpp"

#include <algorithm>

namespace granpipe::pores {

namespace {

// The even permutations of four corners that bring corner k first (double transpositions).
constexpr std::array<std::array<int, 4>, 4> kFirst{
    {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}}};
// The rotations of the last three corners (3-cycles, even) that bring corner k second.
constexpr std::array<std::array<int, 4>, 4> kSecond{
    {{0, 1, 2, 3}, {0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}}};

CellTopology permuted(const CellTopology& c, const std::array<int, 4>& order) {
  CellTopology p;
  for (int k = 0; k < 4; ++k) {
    p.vertices[k] = c.vertices[order[k]];
    p.neighbours[k] = c.neighbours[order[k]];
  }
  return p;
}

}  // namespace

CellTopology canonical(const CellTopology& c) {
  const auto& v = c.vertices;
  const CellTopology first = permuted(c, kFirst[std::min_element(v.begin(), v.end()) - v.begin()]);
  const auto& w = first.vertices;
  return permuted(first, kSecond[std::min_element(w.begin() + 1, w.end()) - w.begin()]);
}

std::vector<std::uint32_t> sorted_places(const std::vector<Corners>& corners, std::size_t points,
                                         int threads) {
  // By first corner (a counting sort), then by the other three within each first corner,
  // the keys of one first corner gathered together first.
  std::vector<std::uint32_t> start(points + 1, 0);
  for (const Corners& c : corners) ++start[c[0] + 1];
  for (std::size_t p = 0; p < points; ++p) start[p + 1] += start[p];
  struct Key {
    Corners corners;
    std::uint32_t cell;
  };
  std::vector<Key> keys(corners.size());
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (std::uint32_t i = 0; i < corners.size(); ++i) keys[next[corners[i][0]]++] = {corners[i], i};
  const auto groups = static_cast<std::ptrdiff_t>(points);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t p = 0; p < groups; ++p) {
    std::sort(keys.begin() + start[p], keys.begin() + start[p + 1],
              [](const Key& a, const Key& b) { return a.corners < b.corners; });
  }
  std::vector<std::uint32_t> place(corners.size());
  for (std::uint32_t k = 0; k < keys.size(); ++k) place[keys[k].cell] = k;
  return place;
}

}  // namespace granpipe::pores
