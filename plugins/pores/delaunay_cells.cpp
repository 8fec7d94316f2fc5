// The triangulation in a file of its own: CGAL is slow to compile.
#include "delaunay_cells.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "granpipe/errors.hpp"

namespace granpipe::pores {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vertex = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using Delaunay =
    CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vertex>>;
using Point = Kernel::Point_3;

Eigen::Vector3d vector_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

// The smallest of the four heights 3V / (area of the opposite face).
double height_of(const std::array<Eigen::Vector3d, 4>& p) {
  const double six_volume = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
  double largest_double_area = 0.0;
  for (int skip = 0; skip < 4; ++skip) {
    const Eigen::Vector3d& a = p[(skip + 1) % 4];
    const Eigen::Vector3d& b = p[(skip + 2) % 4];
    const Eigen::Vector3d& c = p[(skip + 3) % 4];
    largest_double_area = std::max(largest_double_area, (b - a).cross(c - a).norm());
  }
  return six_volume / largest_double_area;
}

DelaunayCell cell_of(const Delaunay::Cell_handle& c) {
  DelaunayCell cell;
  std::array<Eigen::Vector3d, 4> p;
  for (int k = 0; k < 4; ++k) {
    p[k] = vector_of(c->vertex(k)->point());
    cell.vertices[k] = c->vertex(k)->info();
  }
  const Point centre = CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(),
                                          c->vertex(2)->point(), c->vertex(3)->point());
  cell.centre = vector_of(centre);
  cell.radius = (cell.centre - p[0]).norm();
  cell.height = height_of(p);
  return cell;
}

std::string id_of(const Frame& f, std::uint32_t k) { return std::to_string(f.id()[k]); }

// The triangulation keeps one vertex per position: a particle without one shares it.
void refuse_duplicates(const Frame& f, const Centres& centres, const Delaunay& t,
                       const std::vector<std::pair<Point, std::uint32_t>>& points,
                       const std::string& where) {
  if (t.number_of_vertices() == points.size()) return;
  std::vector<bool> kept(points.size(), false);
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v)
    kept[v->info()] = true;
  for (const auto& [p, k] : points) {
    if (kept[k]) continue;
    throw InputError(where + ": expected distinct particle centres, got particles " +
                     id_of(f, centres.particle[t.nearest_vertex(p)->info()]) + " and " +
                     id_of(f, centres.particle[k]) + " at one position");
  }
}

}  // namespace

std::vector<DelaunayCell> delaunay_cells(const Centres& centres, const Frame& frame,
                                         const std::string& where) {
  if (centres.points.size() > std::size_t{UINT32_MAX}) {
    throw InputError(where + ": expected fewer than 2^32 centres and images, got " +
                     std::to_string(centres.points.size()));
  }
  std::vector<std::pair<Point, std::uint32_t>> points;
  points.reserve(centres.points.size());
  for (std::size_t k = 0; k < centres.points.size(); ++k) {
    const Eigen::Vector3d& x = centres.points[k];
    points.emplace_back(Point(x[0], x[1], x[2]), static_cast<std::uint32_t>(k));
  }
  const Delaunay t(points.begin(), points.end());
  refuse_duplicates(frame, centres, t, points, where);
  if (t.dimension() < 3) {
    throw InputError(where + ": expected particle centres spanning a volume, got all of them " +
                     (t.dimension() == 2 ? "in one plane" : "on one line"));
  }
  std::vector<DelaunayCell> cells;
  cells.reserve(t.number_of_finite_cells());
  for (auto c = t.finite_cells_begin(); c != t.finite_cells_end(); ++c) cells.push_back(cell_of(c));
  return cells;
}

}  // namespace granpipe::pores
