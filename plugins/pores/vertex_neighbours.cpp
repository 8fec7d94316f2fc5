#include "vertex_neighbours.hpp"

#include <algorithm>

namespace granpipe::pores {

// Each edge is listed from every cell around it (five or so); the rows are made with the
// repeats, then sorted and the repeats dropped.
VertexNeighbours::VertexNeighbours(const std::vector<DelaunayCell>& cells, std::size_t points)
    : start_(points + 1, 0) {
  for (const DelaunayCell& c : cells)
    for (std::uint32_t v : c.vertices) start_[v + 1] += 3;
  for (std::size_t p = 0; p < points; ++p) start_[p + 1] += start_[p];
  std::vector<std::uint32_t> listed(start_.back());
  std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
  for (const DelaunayCell& c : cells)
    for (std::uint32_t v : c.vertices)
      for (std::uint32_t w : c.vertices)
        if (w != v) listed[next[v]++] = w;
  neighbour_.reserve(listed.size() / 4);
  std::size_t from = 0;
  for (std::size_t p = 0; p < points; ++p) {
    const auto row = listed.begin() + static_cast<std::ptrdiff_t>(from);
    const auto end = listed.begin() + static_cast<std::ptrdiff_t>(start_[p + 1]);
    std::sort(row, end);
    from = start_[p + 1];
    start_[p + 1] = start_[p] + static_cast<std::size_t>(std::unique(row, end) - row);
    neighbour_.insert(neighbour_.end(), row, row + (start_[p + 1] - start_[p]));
  }
}

}  // namespace granpipe::pores
