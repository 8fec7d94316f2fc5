// The Delaunay candidate edges, in a file of their own: CGAL is slow to compile.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <utility>

#include "candidate_edges.hpp"
#include "granpipe/errors.hpp"

namespace granpipe::mst {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using Delaunay3 = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vb3>>;
using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using Delaunay2 = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb2>>;

Edge edge_between(const Frame& f, std::uint32_t a, std::uint32_t b) {
  return {(f.position().row(a) - f.position().row(b)).matrix().norm(), std::min(a, b),
          std::max(a, b)};
}

Kernel::Point_3 point3(const Frame& f, Eigen::Index k) {
  return {f.position()(k, 0), f.position()(k, 1), f.position()(k, 2)};
}
Kernel::Point_2 point2(const Frame& f, Eigen::Index k) {
  return {f.position()(k, 0), f.position()(k, 1)};
}

std::pair<std::uint32_t, std::uint32_t> ends(const Delaunay3::Edge& e) {
  return {e.first->vertex(e.second)->info(), e.first->vertex(e.third)->info()};
}
std::pair<std::uint32_t, std::uint32_t> ends(const Delaunay2::Edge& e) {
  return {e.first->vertex(Delaunay2::cw(e.second))->info(),
          e.first->vertex(Delaunay2::ccw(e.second))->info()};
}

// The triangulation keeps one vertex of particles at one position: the others join it by
// an edge of weight 0, so that every particle is in the graph.
template <class Triangulation, class PointOf>
std::vector<Edge> triangulation_edges(const Frame& f, PointOf point_of) {
  using Point = typename Triangulation::Point;
  const auto n = static_cast<std::size_t>(f.size());
  std::vector<std::pair<Point, std::uint32_t>> points;
  points.reserve(n);
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    points.emplace_back(point_of(f, k), static_cast<std::uint32_t>(k));
  }
  const Triangulation t(points.begin(), points.end());
  std::vector<Edge> edges;
  edges.reserve(8 * n);
  std::vector<bool> kept(n, false);
  for (auto e = t.finite_edges_begin(); e != t.finite_edges_end(); ++e) {
    const auto [a, b] = ends(*e);
    edges.push_back(edge_between(f, a, b));
  }
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v)
    kept[v->info()] = true;
  for (const auto& [p, k] : points) {
    if (!kept[k]) edges.push_back(edge_between(f, k, t.nearest_vertex(p)->info()));
  }
  return edges;
}

}  // namespace

std::vector<Edge> delaunay_edges(const Frame& frame, const std::string& where) {
  for (int a = 0; a < frame.dim; ++a) {
    if (frame.container.periodic(a)) {
      throw InputError(where +
                       ": candidates \"delaunay\" expected a container without periodic "
                       "sides, got a periodic axis " +
                       std::to_string(a) + " (use candidates \"cutoff\")");
    }
  }
  if (frame.size() < 2) return {};
  if (frame.dim == 2) return triangulation_edges<Delaunay2>(frame, point2);
  return triangulation_edges<Delaunay3>(frame, point3);
}

}  // namespace granpipe::mst
