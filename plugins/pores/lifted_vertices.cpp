#include "lifted_vertices.hpp"

#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation.h>
#include <CGAL/Regular_triangulation_traits_adapter.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_data_structure.h>
#include <CGAL/Triangulation_full_cell.h>
#include <CGAL/Triangulation_vertex.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <utility>

#include "sphere_grid.hpp"

namespace granpipe::pores {

namespace {

using Kernel = CGAL::Epick_d<CGAL::Dimension_tag<4>>;
using Traits = CGAL::Regular_triangulation_traits_adapter<Kernel>;
using Tds = CGAL::Triangulation_data_structure<CGAL::Dimension_tag<4>,
                                               CGAL::Triangulation_vertex<Traits, std::uint32_t>,
                                               CGAL::Triangulation_full_cell<Traits>>;
using Lifted = CGAL::Regular_triangulation<Kernel, Tds>;
using FullCell = Lifted::Full_cell_handle;
using Vertex = Lifted::Vertex_handle;

// CGAL's spatial sort of the centres (a Hilbert sort in randomised rounds, its shuffle
// seeded the same every time), each point then located from the one before: what CGAL's
// own insertion of a range does. Sorted bottom up and across instead, each point lay on the
// hull of those before, whose cells every insertion then remade: half as slow again (3.4 s
// against 2.3 s for the pores of 2·10^4 deposited spheres of radii 0.5 to 1).
std::vector<std::uint32_t> insertion_order(const std::vector<Eigen::Vector3d>& centres) {
  using Point = CGAL::Epick::Point_3;
  std::vector<std::pair<Point, std::uint32_t>> points;
  points.reserve(centres.size());
  for (std::size_t k = 0; k < centres.size(); ++k)
    points.emplace_back(Point(centres[k][0], centres[k][1], centres[k][2]),
                        static_cast<std::uint32_t>(k));
  using SortTraits = CGAL::Spatial_sort_traits_adapter_3<
      CGAL::Epick, CGAL::First_of_pair_property_map<std::pair<Point, std::uint32_t>>>;
  CGAL::spatial_sort(points.begin(), points.end(), SortTraits());
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) order[k] = points[k].second;
  return order;
}

Lifted triangulate(const std::vector<Eigen::Vector3d>& centres, const std::vector<double>& radii) {
  Lifted lifted(4);
  FullCell hint;
  for (std::uint32_t i : insertion_order(centres)) {
    const double coordinates[4] = {centres[i][0], centres[i][1], centres[i][2], radii[i]};
    const Lifted::Weighted_point p(Kernel::Point_d(coordinates, coordinates + 4),
                                   2.0 * radii[i] * radii[i]);
    const Vertex v = hint == FullCell() ? lifted.insert(p) : lifted.insert(p, hint);
    if (v == Vertex()) continue;  // hidden: a sphere inside another, touched by no vertex
    v->data() = i;
    hint = v->full_cell();
  }
  return lifted;
}

class Faces {
 public:
  Faces(const Lifted& lifted, const std::vector<Eigen::Vector3d>& centres,
        const std::vector<double>& radii, double length)
      : lifted_(lifted), centres_(centres), radii_(radii), length_(length) {}

  // The tangent sphere of the face of `cell` opposite its vertex `k`, bounded by the two
  // opposite spheres (none for a face of the hull or of a flat triangulation).
  void solve(FullCell cell, int k, std::vector<LiftedVertex>& found) const {
    std::array<std::uint32_t, 4> q{};
    int n = 0;
    for (int j = 0; j <= lifted_.current_dimension(); ++j) {
      if (j == k) continue;
      if (lifted_.is_infinite(cell->vertex(j))) return;
      q[n++] = cell->vertex(j)->data();
    }
    // Solved in the rows' order, not the cell's: which of the face's two cells solves it
    // follows their addresses, and another order of the four rounds otherwise (the pores
    // then changed in their last bits with the number of threads).
    std::sort(q.begin(), q.end());
    std::array<Eigen::Vector3d, 4> x;
    std::array<double, 4> r{};
    for (int j = 0; j < 4; ++j) {
      x[j] = centres_[q[j]];
      r[j] = radii_[q[j]];
    }
    const std::optional<TangentSphere> t = tangent_sphere(x, r);
    if (!t || t->radius < 0.0) return;
    if (k >= 0 && (overlaps(cell->vertex(k), *t) ||
                   overlaps(cell->neighbor(k)->vertex(cell->mirror_index(k)), *t)))
      return;
    found.push_back({q, *t});
  }

 private:
  bool overlaps(Vertex v, const TangentSphere& t) const {
    return !lifted_.is_infinite(v) && overlap_by_more_than(centres_[v->data()], radii_[v->data()],
                                                           t.centre, t.radius, length_);
  }

  const Lifted& lifted_;
  const std::vector<Eigen::Vector3d>& centres_;
  const std::vector<double>& radii_;
  double length_;
};

}  // namespace

std::vector<LiftedVertex> lifted_vertices(const std::vector<Eigen::Vector3d>& centres,
                                          const std::vector<double>& radii, double length) {
  Lifted lifted = triangulate(centres, radii);
  const Faces faces(lifted, centres, radii, length);
  std::vector<LiftedVertex> found;
  if (lifted.current_dimension() == 3) {
    for (auto c = lifted.full_cells_begin(); c != lifted.full_cells_end(); ++c)
      faces.solve(c, -1, found);  // which returns at the hull's cells
  } else if (lifted.current_dimension() == 4) {
    // Each face once, from the full cell of the two that comes first in memory.
    for (auto c = lifted.full_cells_begin(); c != lifted.full_cells_end(); ++c)
      for (int k = 0; k <= 4; ++k)
        if (&*c < &*c->neighbor(k)) faces.solve(c, k, found);
  }
  return found;
}

}  // namespace granpipe::pores
