// The regular triangulation in a file of its own: CGAL is slow to compile.
#include "regular_cells.hpp"

#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cstdint>
#include <utility>

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

Points numbered(const std::vector<Eigen::Vector3d>& x, const std::vector<double>& w,
                std::size_t first_row) {
  Points points;
  points.reserve(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    points.emplace_back(WeightedPoint(cgal::Point(x[k][0], x[k][1], x[k][2]), w[k]),
                        static_cast<std::uint32_t>(first_row + k));
  }
  return points;
}

}  // namespace

struct RegularTriangulation::Impl {
  Regular t;
  std::size_t rows = 0;
};

RegularTriangulation::RegularTriangulation(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<double>& weights)
    : impl_(std::make_unique<Impl>()) {
  insert(points, weights);
}

RegularTriangulation::~RegularTriangulation() = default;

std::vector<DualCell> RegularTriangulation::cells() {
  const Regular& t = impl_->t;
  cgal::number_cells(t);
  std::vector<DualCell> cells(t.number_of_finite_cells());
  auto cell = cells.begin();
  for (auto c = t.finite_cells_begin(); c != t.finite_cells_end(); ++c, ++cell) {
    cgal::fill_dual_cell(c, *cell);
    cell->centre =
        cgal::vector_of(CGAL::weighted_circumcenter(c->vertex(0)->point(), c->vertex(1)->point(),
                                                    c->vertex(2)->point(), c->vertex(3)->point()));
  }
  return cells;
}

void RegularTriangulation::insert(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<double>& weights) {
  const Points numbered_points = numbered(points, weights, impl_->rows);
  impl_->t.insert(numbered_points.begin(), numbered_points.end());
  impl_->rows += points.size();
}

}  // namespace granpipe::pores
