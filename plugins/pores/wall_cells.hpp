#pragma once
// The cells of the particles at plane walls. The triangulation of the centres leaves them
// unbounded or reaching through a wall; cut from the container's box by the radical planes
// of their neighbours in the triangulation, they end at the walls exactly, as they would
// with mirror images of the particles beyond the walls: a particle and its mirror have
// equal weights, so their radical plane is the wall, and the mirror of another particle is
// farther than that particle from every point inside, so it cuts nothing there.
#include <cstdint>
#include <vector>

#include "cell_bounds.hpp"
#include "power_volumes.hpp"

namespace granpipe::pores {

// Replaces the volume, flags and shortfall of each point of `rows` in `v` by those of its
// cell cut from bounds.cut_box(); an empty cut cell (a sphere whose cell lies beyond a
// wall) has no kSeen, as a hidden sphere.
template <class Cell>
void cut_at_walls(PowerVolumes& v, const std::vector<std::uint32_t>& rows,
                  const WeightedPoints& points, const std::vector<Cell>& cells,
                  const CellBounds& bounds, int threads);

}  // namespace granpipe::pores
