#pragma once
// What the CGAL triangulations of this plugin share: the kernel, and their finite cells
// read out in the order of cell_order.hpp.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <omp.h>

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "cell_order.hpp"
#include "dual_cell.hpp"

namespace granpipe::pores::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

inline Point point_of(const Eigen::Vector3d& x) { return {x[0], x[1], x[2]}; }
inline Eigen::Vector3d vector_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

// A finite cell's corners (vertex infos: rows), canonical.
template <class CellHandle>
Corners corners_of(const CellHandle& c) {
  CellTopology cell;
  for (int k = 0; k < 4; ++k) cell.vertices[k] = c->vertex(k)->info();
  return canonical(cell).vertices;
}

// A finite cell's corners and neighbours (cell infos), canonical.
template <class CellHandle>
CellTopology topology_of(const CellHandle& c) {
  CellTopology cell;
  for (int k = 0; k < 4; ++k) {
    cell.vertices[k] = c->vertex(k)->info();
    cell.neighbours[k] = c->neighbor(k)->info();
  }
  return canonical(cell);
}

// Runs of items made by make(k) for k in [0, n), on `threads`, each a run, joined in order.
template <class Item, class Make>
std::vector<Item> made_in_runs(std::size_t n, int threads, Make make) {
  std::vector<std::vector<Item>> runs(static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    const auto part = static_cast<std::size_t>(omp_get_thread_num());
    const auto parts = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t first = n * part / parts, end = n * (part + 1) / parts;
    runs[part].reserve(end - first);
    for (std::size_t k = first; k < end; ++k) runs[part].push_back(make(k));
  }
  std::vector<Item> items = std::move(runs.front());
  for (std::size_t r = 1; r < runs.size(); ++r)
    items.insert(items.end(), runs[r].begin(), runs[r].end());
  return items;
}

// The finite cells, made by make(topology) from their corners and neighbours, sorted
// (cell_order.hpp); the cells' infos number them so (the infinite ones kHull).
template <class Cell, class Triangulation, class Make>
std::vector<Cell> sorted_cells(const Triangulation& t, std::size_t points, int threads, Make make) {
  std::vector<typename Triangulation::Cell_handle> found;
  found.reserve(t.number_of_cells());
  for (auto c = t.finite_cells_begin(); c != t.finite_cells_end(); ++c) found.push_back(c);
  const std::vector<Corners> corners = made_in_runs<Corners>(
      found.size(), threads, [&](std::size_t i) { return corners_of(found[i]); });
  const std::vector<std::uint32_t> place = sorted_places(corners, points, threads);
  std::uint32_t finite = 0;
  for (auto c = t.all_cells_begin(); c != t.all_cells_end(); ++c)
    c->info() = t.is_infinite(c) ? kHull : place[finite++];
  std::vector<typename Triangulation::Cell_handle> in_order(found.size());
  for (std::size_t i = 0; i < found.size(); ++i) in_order[place[i]] = found[i];
  return made_in_runs<Cell>(in_order.size(), threads,
                            [&](std::size_t k) { return make(topology_of(in_order[k])); });
}

}  // namespace granpipe::pores::cgal
