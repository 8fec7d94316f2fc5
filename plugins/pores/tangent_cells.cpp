#include "tangent_cells.hpp"

#include <array>
#include <cstdint>
#include <optional>

#include "sphere_grid.hpp"
#include "tangent_sphere.hpp"

namespace granpipe::pores {

NonPoreCells tangent_cells(std::vector<DelaunayCell>& cells, const Centres& centres,
                           const Frame& frame, double mean_radius, double length, int threads) {
  // Every sphere is looked at, not only those next to the four in the triangulation: a
  // sphere a hundred times wider reaches past them (radii 0.02 and 2: a pore inside it).
  std::vector<double> radius(centres.points.size());
  for (std::size_t p = 0; p < radius.size(); ++p) radius[p] = frame.radius()[centres.particle[p]];
  const SphereGrid grid(centres.points, std::move(radius), 2.0 * mean_radius);
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
    } else if (grid.overlaps_any(sphere->centre, sphere->radius, length)) {
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
