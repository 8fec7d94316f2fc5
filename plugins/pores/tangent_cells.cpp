#include "tangent_cells.hpp"

#include <array>
#include <optional>

#include "tangent_sphere.hpp"

namespace granpipe::pores {

TangentCells tangent_cells(const std::vector<DelaunayCell>& cells, const Centres& centres,
                           const Frame& frame, double mean_radius, double flat_height) {
  TangentCells tangent;
  tangent.cells.reserve(cells.size());
  for (const DelaunayCell& cell : cells) {
    if (cell.height < flat_height) {
      tangent.cells.push_back(cell);
      continue;
    }
    std::array<Eigen::Vector3d, 4> x;
    std::array<double, 4> r{};
    for (int k = 0; k < 4; ++k) {
      x[k] = centres.points[cell.vertices[k]];
      r[k] = frame.radius()[centres.particle[cell.vertices[k]]];
    }
    const std::optional<TangentSphere> sphere = tangent_sphere(x, r);
    if (!sphere) {
      tangent.untangent.push_back(cell.centre);
      continue;
    }
    DelaunayCell& t = tangent.cells.emplace_back(cell);
    t.centre = sphere->centre;
    t.radius = sphere->radius + mean_radius;
  }
  return tangent;
}

}  // namespace granpipe::pores
