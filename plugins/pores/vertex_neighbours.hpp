#pragma once
// The neighbours of every point of a triangulation (the other ends of its edges), in
// compressed rows: those of point p are neighbour[start[p]] ... neighbour[start[p + 1] - 1].
#include <cstdint>
#include <span>
#include <vector>

#include "delaunay_cells.hpp"

namespace granpipe::pores {

class VertexNeighbours {
 public:
  VertexNeighbours(const std::vector<DelaunayCell>& cells, std::size_t points);
  std::span<const std::uint32_t> of(std::uint32_t p) const {
    return {neighbour_.data() + start_[p], neighbour_.data() + start_[p + 1]};
  }

 private:
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> neighbour_;
};

}  // namespace granpipe::pores
