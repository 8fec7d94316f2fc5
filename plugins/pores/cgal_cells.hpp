#pragma once
// What the CGAL triangulations of this plugin share: the kernel, and their finite cells
// read out in the triangulation's order. The points are inserted by CGAL's range
// insertion (a spatial sort in randomised rounds), whose cells lie in memory partly
// scattered; the passes over them fetch what they read of other cells ahead (sorting the
// cells by their corners' rows took longer than it saved).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <omp.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <iterator>
#include <vector>

#include "dual_cell.hpp"
#include "granpipe/parallel_errors.hpp"

namespace granpipe::pores::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

inline Point point_of(const Eigen::Vector3d& x) { return {x[0], x[1], x[2]}; }
inline Eigen::Vector3d vector_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

// Items made by make(k) for k in [0, n) on `threads`, each a run of them, joined in order.
template <class Item, class Make>
std::vector<Item> made_in_runs(std::size_t n, int threads, Make make) {
  std::vector<std::vector<Item>> runs(static_cast<std::size_t>(threads));
  ParallelErrors errors;
#pragma omp parallel num_threads(threads)
  errors.run([&] {
    const auto part = static_cast<std::size_t>(omp_get_thread_num());
    const auto parts = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t first = n * part / parts, end = n * (part + 1) / parts;
    // The first run takes the others after it: room for all, so that joining them copies
    // only theirs (the whole array once more, and its pages, when the first reallocated).
    runs[part].reserve(part == 0 ? n : end - first);
    for (std::size_t k = first; k < end; ++k) runs[part].push_back(make(k));
  });
  errors.rethrow();
  std::vector<Item> items = std::move(runs.front());
  for (std::size_t r = 1; r < runs.size(); ++r)
    items.insert(items.end(), runs[r].begin(), runs[r].end());
  return items;
}

// A cell's neighbours' infos and corners' points, fetched into the cache some cells ahead
// of their reading: the neighbours lie anywhere in CGAL's container, and waiting on them
// and on the corners was most of the reading's time.
constexpr std::size_t kPrefetchAhead = 8;

template <class CellHandle>
void prefetch_around(const CellHandle& c) {
  for (int k = 0; k < 4; ++k) {
    __builtin_prefetch(&c->neighbor(k)->info());
    __builtin_prefetch(&c->vertex(k)->point());
  }
}

// The finite cells, made by make(topology, handle) from their corners (vertex infos: rows)
// and neighbours, in the triangulation's order; the cells' infos number them so (the
// infinite ones kHull). The handle gives make the corners' points off the vertices, whose
// memory reading the infos fetched already (an array of the points by row is a second
// random read per corner).
template <class Cell, class Triangulation, class Make>
std::vector<Cell> cells_of(const Triangulation& t, int threads, Make make) {
  std::vector<typename Triangulation::Cell_handle> finite;
  finite.reserve(t.number_of_cells());
  for (auto c = t.all_cells_begin(); c != t.all_cells_end(); ++c) {
    c->info() = t.is_infinite(c) ? kHull : static_cast<std::uint32_t>(finite.size());
    if (!t.is_infinite(c)) finite.push_back(c);
  }
  return made_in_runs<Cell>(finite.size(), threads, [&](std::size_t i) {
    if (i + kPrefetchAhead < finite.size()) prefetch_around(finite[i + kPrefetchAhead]);
    CellTopology cell;
    for (int k = 0; k < 4; ++k) {
      cell.vertices[k] = finite[i]->vertex(k)->info();
      cell.neighbours[k] = finite[i]->neighbor(k)->info();
    }
    return make(cell, finite[i]);
  });
}

// The points of a cell's four corners, in its vertices' order.
template <class CellHandle>
auto corner_points(const CellHandle& c) {
  return std::array{c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                    c->vertex(3)->point()};
}

// The rows of the points on the hull (their cells unbounded).
template <class Triangulation>
std::vector<std::uint32_t> hull_rows(const Triangulation& t) {
  std::vector<typename Triangulation::Vertex_handle> hull;
  t.finite_adjacent_vertices(t.infinite_vertex(), std::back_inserter(hull));
  std::vector<std::uint32_t> rows;
  for (const auto& v : hull) rows.push_back(v->info());
  return rows;
}

}  // namespace granpipe::pores::cgal
