#pragma once
// A candidate edge of the MST: two particles (i < j) and the edge's weight, the centre
// distance (times the elongation once selected).
#include <cstdint>

namespace granpipe::mst {

struct Edge {
  double weight = 0.0;
  std::uint32_t i = 0, j = 0;
};

}  // namespace granpipe::mst
