// The regular triangulation in a file of its own: CGAL is slow to compile.
#include "regular_cells.hpp"

#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "cgal_cells.hpp"

namespace granpipe::pores {

namespace {

using cgal::Kernel;
using WeightedPoint = Kernel::Weighted_point_3;
using Vertex =
    CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel,
                                                CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
using Cell =
    CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, Kernel,
                                              CGAL::Regular_triangulation_cell_base_3<Kernel>>;
using Regular =
    CGAL::Regular_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vertex, Cell>>;
using Points = std::vector<std::pair<WeightedPoint, std::uint32_t>>;

Points numbered(const std::vector<Eigen::Vector3d>& x, const std::vector<double>& w) {
  Points points;
  points.reserve(x.size());
  for (std::size_t k = 0; k < x.size(); ++k)
    points.emplace_back(WeightedPoint(cgal::point_of(x[k]), w[k]), static_cast<std::uint32_t>(k));
  return points;
}

}  // namespace

struct RegularTriangulation::Impl {
  Regular t;
};

RegularTriangulation::RegularTriangulation(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<double>& weights)
    : impl_(std::make_unique<Impl>()) {
  const Points numbered_points = numbered(points, weights);
  impl_->t.insert(numbered_points.begin(), numbered_points.end());
}

RegularTriangulation::~RegularTriangulation() = default;

std::vector<DualCell> RegularTriangulation::cells(int threads) {
  return cgal::cells_of<DualCell>(impl_->t, threads, [&](const CellTopology& c, auto handle) {
    DualCell cell;
    static_cast<CellTopology&>(cell) = c;
    const auto p = cgal::corner_points(handle);
    cell.centre = cgal::vector_of(CGAL::weighted_circumcenter(p[0], p[1], p[2], p[3]));
    return cell;
  });
}

std::vector<std::uint32_t> RegularTriangulation::hull() const { return cgal::hull_rows(impl_->t); }

}  // namespace granpipe::pores
