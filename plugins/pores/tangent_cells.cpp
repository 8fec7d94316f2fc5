#include "tangent_cells.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "granpipe/parallel_errors.hpp"
#include "sphere_grid.hpp"
#include "tangent_sphere.hpp"
#include "vertex_neighbours.hpp"

namespace granpipe::pores {

namespace {

// Spheres of radii in (lo, hi] binned on a grid of their own. Those more than twice the
// mean radius wide reach past the spheres next to a cell in the triangulation (at radii
// 0.02 and 1, a sphere beyond them overlapped the tangent sphere of four small ones by
// 0.32); few in the packings that have them (an intruder among beads), so their grid
// answers for every cell at little cost. The others, on a grid of their own, answer
// for the cells whose sphere may be counted: a sphere no neighbour of the four may overlap
// it too where centres are nearly cospherical (a simple cubic block of radii 1 +- 1e-3
// counted a pore overlapped by 9e-4).
class SpheresOfRadii {
 public:
  SpheresOfRadii(const Centres& centres, const Frame& frame, double lo, double hi) {
    std::vector<double> radius;
    for (std::uint32_t p = 0; p < centres.points.size(); ++p) {
      const double r = frame.radius()[centres.particle[p]];
      if (r <= lo || r > hi) continue;
      point_.push_back(p);
      centre_.push_back(centres.points[p]);
      radius.push_back(r);
    }
    if (point_.empty()) return;
    const double widest = *std::max_element(radius.begin(), radius.end());
    grid_.emplace(centre_, std::move(radius), 2.0 * widest);
  }

  // Whether one of them, other than the cell's own four, overlaps the sphere by more than
  // `length`.
  bool overlap(const TangentSphere& sphere, const DelaunayCell& cell, double length) const {
    if (!grid_) return false;
    return grid_->overlaps_any(sphere.centre, sphere.radius, length, [&](std::uint32_t k) {
      return std::find(cell.vertices.begin(), cell.vertices.end(), point_[k]) ==
             cell.vertices.end();
    });
  }

 private:
  std::vector<std::uint32_t> point_;  // their index among the centres
  std::vector<Eigen::Vector3d> centre_;
  std::optional<SphereGrid> grid_;
};

// Whether a sphere next to one of the cell's four overlaps the tangent sphere by more
// than `length`.
bool overlaps_a_neighbour(const DelaunayCell& cell, const TangentSphere& sphere,
                          const VertexNeighbours& neighbours, const Centres& centres,
                          const Frame& frame, double length) {
  for (std::uint32_t v : cell.vertices) {
    for (std::uint32_t w : neighbours.of(v)) {
      if (std::find(cell.vertices.begin(), cell.vertices.end(), w) != cell.vertices.end()) continue;
      if (overlap_by_more_than(centres.points[w], frame.radius()[centres.particle[w]],
                               sphere.centre, sphere.radius, length))
        return true;
    }
  }
  return false;
}

}  // namespace

NonPoreCells tangent_cells(std::vector<DelaunayCell>& cells, const Centres& centres,
                           const Frame& frame, double mean_radius, const MayCount& may_count,
                           double length, int threads) {
  const VertexNeighbours neighbours(cells, centres.points.size());
  constexpr double kWide = 2.0;  // radii above kWide R are wide
  const SpheresOfRadii wide(centres, frame, kWide * mean_radius, INFINITY);
  const SpheresOfRadii narrow(centres, frame, -INFINITY, kWide * mean_radius);
  // A sphere no cell's corners name may overlap the sphere of a cell that may be counted:
  // those are checked against every sphere (the neighbours first, as most overlaps are
  // theirs). The others against the neighbours and the wide spheres: the hull cells above
  // a free surface or of the images, whose spheres are huge, would scan every sphere.
  const auto overlapped = [&](const DelaunayCell& cell, const TangentSphere& sphere) {
    return overlaps_a_neighbour(cell, sphere, neighbours, centres, frame, length) ||
           wide.overlap(sphere, cell, length) ||
           (may_count(sphere.centre) && narrow.overlap(sphere, cell, length));
  };
  // Each cell's circumcentre before it becomes its tangent sphere's, and why it is left out.
  enum Kind : std::uint8_t { kPore, kUntangent, kFifthSphere };
  std::vector<Kind> kind(cells.size(), kPore);
  std::vector<Eigen::Vector3d> circumcentre(cells.size());
  const auto n = static_cast<std::ptrdiff_t>(cells.size());
  ParallelErrors errors;
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    errors.run([&] {
      DelaunayCell& cell = cells[i];
      circumcentre[i] = cell.centre;
      if (cell.flat) return;
      std::array<Eigen::Vector3d, 4> x;
      std::array<double, 4> r{};
      for (int k = 0; k < 4; ++k) {
        x[k] = centres.points[cell.vertices[k]];
        r[k] = frame.radius()[centres.particle[cell.vertices[k]]];
      }
      const std::optional<TangentSphere> sphere = tangent_sphere(x, r);
      if (!sphere) {
        kind[i] = kUntangent;
      } else if (overlapped(cell, *sphere)) {
        kind[i] = kFifthSphere;
      } else {
        cell.centre = sphere->centre;
        cell.radius = sphere->radius + mean_radius;
      }
      cell.pore = kind[i] == kPore;
    });
  }
  errors.rethrow();
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
