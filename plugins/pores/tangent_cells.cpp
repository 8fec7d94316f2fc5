#include "tangent_cells.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
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
                           const Frame& frame, double mean_radius, double length, int threads) {
  const VertexNeighbours neighbours(cells, centres.points.size());
  // Each cell's circumcentre before it becomes its tangent sphere's, and why it is left out.
  enum Kind : std::uint8_t { kPore, kUntangent, kFifthSphere };
  std::vector<Kind> kind(cells.size(), kPore);
  std::vector<Eigen::Vector3d> circumcentre(cells.size());
  const auto n = static_cast<std::ptrdiff_t>(cells.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    DelaunayCell& cell = cells[i];
    circumcentre[i] = cell.centre;
    if (cell.flat) continue;
    std::array<Eigen::Vector3d, 4> x;
    std::array<double, 4> r{};
    for (int k = 0; k < 4; ++k) {
      x[k] = centres.points[cell.vertices[k]];
      r[k] = frame.radius()[centres.particle[cell.vertices[k]]];
    }
    const std::optional<TangentSphere> sphere = tangent_sphere(x, r);
    if (!sphere) {
      kind[i] = kUntangent;
    } else if (overlaps_a_fifth(cell, *sphere, neighbours, centres, frame, length)) {
      kind[i] = kFifthSphere;
    } else {
      cell.centre = sphere->centre;
      cell.radius = sphere->radius + mean_radius;
    }
    cell.pore = kind[i] == kPore;
  }
  NonPoreCells left_out;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (kind[i] == kUntangent) left_out.untangent.push_back(circumcentre[i]);
    if (kind[i] == kFifthSphere) {
      left_out.fifth_sphere.push_back(circumcentre[i]);
      left_out.fifth_sphere_cells.push_back(i);
    }
  }
  return left_out;
}

}  // namespace granpipe::pores
