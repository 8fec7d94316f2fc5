#pragma once
// A candidate edge of the MST: two particles (i < j) and the edge's weight, the centre
// distance (times the elongation once selected).
#include <cstdint>
#include <tuple>

namespace granpipe::mst {

struct Edge {
  double weight = 0.0;
  std::uint32_t i = 0, j = 0;
};

// The order Kruskal visits edges in: by weight, ties by (i, j), so that equal lengths
// (lattices) give one answer whatever order the edges were found in.
inline bool lighter(const Edge& a, const Edge& b) {
  return std::tie(a.weight, a.i, a.j) < std::tie(b.weight, b.i, b.j);
}

}  // namespace granpipe::mst
