#include "bernal_holes.hpp"

#include <cmath>

namespace granpipe::pores {

const std::array<BernalHole, 5>& bernal_holes() {
  // The paper gives xi to three digits; the octahedron appears as Bernal's half-octahedron.
  static const std::array<BernalHole, 5> holes{{{"tetrahedron", 0.225, 73.0, 48.4},
                                                {"tetragonal dodecahedron", 0.353, 3.1, 14.8},
                                                {"half-octahedron", 0.414, 20.3, 26.9},
                                                {"trigonal prism", 0.528, 3.2, 7.8},
                                                {"archimedean antiprism", 0.645, 0.4, 2.1}}};
  return holes;
}

std::size_t nearest_hole(double xi) {
  const auto& holes = bernal_holes();
  const std::size_t n = holes.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double below = k > 0 ? holes[k].xi - holes[k - 1].xi : holes[1].xi - holes[0].xi;
    const double above = k + 1 < n ? holes[k + 1].xi - holes[k].xi : holes[k].xi - holes[k - 1].xi;
    if (xi >= holes[k].xi - below / 2 && xi < holes[k].xi + above / 2) return k;
  }
  return n;
}

}  // namespace granpipe::pores
