#pragma once
// The finite cells of a triangulation in an order that depends on the points alone. CGAL's
// own order follows the history of the insertions, and a cell's corners come in any of
// twelve rotations: whatever is computed from the cells (circumcentres, sums over cells)
// would round differently after another history (images added to a triangulation against
// all of them at once). In the order made here every result is the same bits, and cells
// near each other in the packing are near each other in memory (the rows follow a Morton
// curve), which the passes over the cells profit from.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dual_cell.hpp"

namespace granpipe::pores {

using Corners = std::array<std::uint32_t, 4>;

// The corners start with the smallest row and the next is the smallest of the other
// three, by an even permutation (orientation kept), the neighbours permuted alike.
CellTopology canonical(const CellTopology& c);

// The place of each cell, given its canonical corners, among the cells sorted by their
// corners' rows. Rows are below `points`.
std::vector<std::uint32_t> sorted_places(const std::vector<Corners>& corners, std::size_t points,
                                         int threads);

}  // namespace granpipe::pores
