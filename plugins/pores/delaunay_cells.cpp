// The triangulation in a file of its own: CGAL is slow to compile.
#include "delaunay_cells.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "cgal_cells.hpp"
#include "granpipe/errors.hpp"

namespace granpipe::pores {

namespace {

using cgal::Kernel;
using cgal::Point;
using cgal::vector_of;
using Vertex = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using Cell =
    CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, Kernel,
                                              CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Delaunay =
    CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vertex, Cell>>;
using Points = std::vector<std::pair<Point, std::uint32_t>>;

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
  cgal::fill_dual_cell(c, cell);
  std::array<Eigen::Vector3d, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = vector_of(c->vertex(k)->point());
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
                       const Points& points, const std::string& where) {
  if (t.number_of_vertices() == points.size()) return;
  std::vector<bool> kept(points.size(), false);
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v)
    kept[v->info()] = true;
  for (const auto& [p, k] : points) {
    if (kept[k]) continue;
    // Named in the frame's order, whichever the triangulation kept.
    const auto [first, second] =
        std::minmax(centres.particle[t.nearest_vertex(p)->info()], centres.particle[k]);
    throw InputError(where + ": expected distinct particle centres, got particles " +
                     id_of(f, first) + " and " + id_of(f, second) + " at one position");
  }
}

Points numbered(const std::vector<Eigen::Vector3d>& x, std::size_t first_row) {
  Points points;
  points.reserve(x.size());
  for (std::size_t k = 0; k < x.size(); ++k)
    points.emplace_back(Point(x[k][0], x[k][1], x[k][2]),
                        static_cast<std::uint32_t>(first_row + k));
  return points;
}

}  // namespace

struct DelaunayTriangulation::Impl {
  Delaunay t;
  std::size_t rows = 0;  // points inserted
};

DelaunayTriangulation::DelaunayTriangulation(const Centres& centres, const Frame& frame,
                                             const std::string& where)
    : impl_(std::make_unique<Impl>()) {
  // Room for the mirror images inserted later, within the row numbers.
  if (centres.points.size() > std::size_t{UINT32_MAX / 4}) {
    throw InputError(where + ": expected fewer than 2^30 centres and images, got " +
                     std::to_string(centres.points.size()));
  }
  const Points points = numbered(centres.points, 0);
  impl_->t.insert(points.begin(), points.end());
  impl_->rows = points.size();
  refuse_duplicates(frame, centres, impl_->t, points, where);
  if (impl_->t.dimension() < 3) {
    throw InputError(where + ": expected particle centres spanning a volume, got all of them " +
                     (impl_->t.dimension() == 2 ? "in one plane" : "on one line"));
  }
}

DelaunayTriangulation::~DelaunayTriangulation() = default;

std::vector<DelaunayCell> DelaunayTriangulation::cells() {
  const Delaunay& t = impl_->t;
  cgal::number_cells(t);
  std::vector<DelaunayCell> cells;
  cells.reserve(t.number_of_finite_cells());
  for (auto c = t.finite_cells_begin(); c != t.finite_cells_end(); ++c) cells.push_back(cell_of(c));
  return cells;
}

void DelaunayTriangulation::insert(const std::vector<Eigen::Vector3d>& points) {
  const Points numbered_points = numbered(points, impl_->rows);
  impl_->t.insert(numbered_points.begin(), numbered_points.end());
  impl_->rows += points.size();
}

}  // namespace granpipe::pores
