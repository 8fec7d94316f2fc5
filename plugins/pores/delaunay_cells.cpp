// The triangulation in a file of its own: CGAL is slow to compile.
#include "delaunay_cells.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "cgal_cells.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe::pores {

namespace {

using cgal::Kernel;
using cgal::Point;
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

// How far the circumcentre c of corners p_i may move when each is moved by at most
// d = eps |p_i| (its coordinates' rounding): solving (p_i - p_0) . c' = |p_i - p_0|^2 / 2,
// c' = c - p_0, the right side and matrix move by 2dL and 2d (L the longest edge, r = |c'|),
// and the inverse matrix is at most sqrt(3) L^2 / 6V, hence 6 d L^2 (L + r) / 6V; plus the
// rounding of the formula in cell_of (its terms at most L^4, and 6V's L^3), a few eps L
// in place of d. Nothing for a flat cell, which is no pore.
float uncertainty_of(const std::array<Eigen::Vector3d, 4>& p, double longest_squared, double radius,
                     double six_volume) {
  double farthest = 0.0;
  for (const Eigen::Vector3d& x : p) farthest = std::max(farthest, x.norm());
  const double edge = std::sqrt(longest_squared);
  const double bound = std::numeric_limits<double>::epsilon() * (6.0 * farthest + 64.0 * edge) *
                       longest_squared * (edge + radius) / std::abs(six_volume);
  return static_cast<float>(bound);
}

// The circumsphere from the corners relative to the first (as CGAL's circumcenter), and
// whether the cell is lower than `length`. Its height is at least 6V over the longest edge
// squared (a face's double area is at most that): only the cells this leaves in doubt have
// their heights computed.
DelaunayCell cell_of(const CellTopology& topology, const std::array<Point, 4>& corners,
                     double length) {
  DelaunayCell cell;
  static_cast<CellTopology&>(cell) = topology;
  const std::array<Eigen::Vector3d, 4> p{cgal::vector_of(corners[0]), cgal::vector_of(corners[1]),
                                         cgal::vector_of(corners[2]), cgal::vector_of(corners[3])};
  const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const Eigen::Vector3d bc = b.cross(c);
  const double six_volume = a.dot(bc);
  const Eigen::Vector3d offset =
      (a.squaredNorm() * bc + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b)) /
      (2.0 * six_volume);
  cell.centre = p[0] + offset;
  cell.radius = offset.norm();
  const auto [shortest, longest] =
      std::minmax({a.squaredNorm(), b.squaredNorm(), c.squaredNorm(), (b - a).squaredNorm(),
                   (c - a).squaredNorm(), (c - b).squaredNorm()});
  cell.flat = std::abs(six_volume) < 1.001 * length * longest && height_of(p) < length;
  cell.close_corners = shortest < length * length;
  if (!cell.flat) cell.uncertainty = uncertainty_of(p, longest, cell.radius, six_volume);
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

// In the order of CGAL's insertion of a range (a spatial sort in randomised rounds, BRIO,
// its random shuffle seeded the same every time), each point located from the one
// before. About a fifth faster than inserting the points in their rows' Morton order,
// whose cells lay in memory about in that order, which the passes over the cells profited
// from: at 10^6 deposited spheres the insertion saves more than the scattered cells cost
// the passes, at 10^5 about as much. The (point, row) pairs are sorted themselves: CGAL's
// insertion of pairs sorts their indices, each comparison then reading two points
// elsewhere (the same order, to the bit: the sort compares the same points). A point at
// the position of another takes its vertex (refuse_duplicates).
void insert_points(Delaunay& t, Points points) {
  using Traits = CGAL::Spatial_sort_traits_adapter_3<
      Kernel, CGAL::First_of_pair_property_map<std::pair<Point, std::uint32_t>>>;
  CGAL::spatial_sort(points.begin(), points.end(), Traits());
  Delaunay::Vertex_handle last;
  for (const auto& [p, row] : points) {
    last = t.insert(p, last);
    last->info() = row;
  }
}

}  // namespace

void refuse_close_centres(const std::vector<DelaunayCell>& cells, const Centres& centres,
                          const Frame& frame, double length, const std::string& where) {
  const auto close = std::find_if(cells.begin(), cells.end(),
                                  [](const DelaunayCell& c) { return c.close_corners; });
  if (close == cells.end()) return;
  std::array<std::uint32_t, 2> pair{};
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double d =
          (centres.points[close->vertices[i]] - centres.points[close->vertices[j]]).norm();
      if (d < nearest) {
        nearest = d;
        pair = {centres.particle[close->vertices[i]], centres.particle[close->vertices[j]]};
      }
    }
  const auto [first, second] = std::minmax(pair[0], pair[1]);
  throw InputError(where + ": expected distinct particle centres, got particles " +
                   id_of(frame, first) + " and " + id_of(frame, second) + " " +
                   format_number(nearest) + " apart, closer than tolerance times the mean " +
                   "radius (" + format_number(length) + "), by which pores are told apart");
}

struct DelaunayTriangulation::Impl {
  Delaunay t;
  std::size_t rows = 0;  // points inserted, the images of wider skins included
};

DelaunayTriangulation::DelaunayTriangulation(const Centres& centres, const Frame& frame,
                                             const std::string& where)
    : impl_(std::make_unique<Impl>()) {
  // Room for the images of a wider skin inserted later, within the row numbers.
  if (centres.points.size() > std::size_t{UINT32_MAX / 4}) {
    throw InputError(where + ": expected fewer than 2^30 centres and images, got " +
                     std::to_string(centres.points.size()));
  }
  const Points points = numbered(centres.points, 0);
  insert_points(impl_->t, points);
  impl_->rows = points.size();
  refuse_duplicates(frame, centres, impl_->t, points, where);
  if (impl_->t.dimension() < 3) {
    throw InputError(where + ": expected particle centres spanning a volume, got all of them " +
                     (impl_->t.dimension() == 2 ? "in one plane" : "on one line"));
  }
}

DelaunayTriangulation::~DelaunayTriangulation() = default;

std::vector<DelaunayCell> DelaunayTriangulation::cells(double length, int threads) {
  return cgal::cells_of<DelaunayCell>(impl_->t, threads, [&](const CellTopology& c, auto cell) {
    return cell_of(c, cgal::corner_points(cell), length);
  });
}

std::vector<std::uint32_t> DelaunayTriangulation::hull() const { return cgal::hull_rows(impl_->t); }

void DelaunayTriangulation::insert(const std::vector<Eigen::Vector3d>& points) {
  insert_points(impl_->t, numbered(points, impl_->rows));
  impl_->rows += points.size();
}

}  // namespace granpipe::pores
