#include "tangent_cells.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include "tangent_sphere.hpp"
#include "vertex_neighbours.hpp"

namespace granpipe::pores {

namespace {

// Whether a sphere next to one of the cell's four overlaps the tangent sphere by more
// than `length`.
bool overlaps_a_fifth(const DelaunayCell& cell, const TangentSphere& sphere,
                      const VertexNeighbours& neighbours, const Centres& centres,
                      const Frame& frame, double length) {
  for (std::uint32_t v : cell.vertices) {
    for (std::uint32_t w : neighbours.of(v)) {
      if (std::find(cell.vertices.begin(), cell.vertices.end(), w) != cell.vertices.end()) continue;
      const double reach = frame.radius()[centres.particle[w]] + sphere.radius - length;
      if (reach > 0.0 && (centres.points[w] - sphere.centre).squaredNorm() < reach * reach)
        return true;
    }
  }
  return false;
}

}  // namespace

NonPoreCells tangent_cells(std::vector<DelaunayCell>& cells, const Centres& centres,
                           const Frame& frame, double mean_radius, double length) {
  const VertexNeighbours neighbours(cells, centres.points.size());
  NonPoreCells left_out;
  for (DelaunayCell& cell : cells) {
    if (cell.height < length) continue;
    std::array<Eigen::Vector3d, 4> x;
    std::array<double, 4> r{};
    for (int k = 0; k < 4; ++k) {
      x[k] = centres.points[cell.vertices[k]];
      r[k] = frame.radius()[centres.particle[cell.vertices[k]]];
    }
    const std::optional<TangentSphere> sphere = tangent_sphere(x, r);
    if (!sphere) {
      left_out.untangent.push_back(cell.centre);
      cell.pore = false;
      continue;
    }
    if (overlaps_a_fifth(cell, *sphere, neighbours, centres, frame, length)) {
      left_out.fifth_sphere.push_back(cell.centre);
      cell.pore = false;
      continue;
    }
    cell.centre = sphere->centre;
    cell.radius = sphere->radius + mean_radius;
  }
  return left_out;
}

}  // namespace granpipe::pores
