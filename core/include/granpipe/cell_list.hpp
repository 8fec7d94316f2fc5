#pragma once
// Cell-list neighbour search in 2D and 3D, for boxes with walls, open sides or periodic
// sides (minimum image). Building is O(N); a pair loop visits only neighbouring cells.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "granpipe/container.hpp"
#include "granpipe/frame.hpp"

namespace granpipe {

class CellList {
 public:
  // `cutoff` is the largest centre distance any query will ask for. Along a periodic
  // axis the box must be at least 2 * cutoff long (minimum image), and along every axis
  // at most 1e9 * cutoff. An InputError says so, after `where` (e.g. the frame).
  CellList(const Coordinates& position, const Container& container, int dim, double cutoff,
           const std::string& where);
  CellList(const Coordinates& position, const Container& container, int dim, double cutoff)
      : CellList(position, container, dim, cutoff, "") {}

  // Calls f(i, j, d, r2) once for every pair i < j with |d|^2 = r2 <= cutoff^2, where
  // d = x_j - x_i (minimum image) is a const double* of length dim.
  template <class F>
  void for_each_pair(F&& f) const;

  // Calls f(j, d, r2) for every particle j within `radius` (<= cutoff) of point x,
  // d = x_j - x (minimum image).
  template <class F>
  void for_each_near(const double* x, double radius, F&& f) const;

  // Applies the minimum-image convention to a separation vector.
  void minimum_image(double* d) const;
  int dim() const { return dim_; }
  double cutoff() const { return cutoff_; }

 private:
  int cell_of(const double* x, std::array<int, 3>& c) const;
  template <class F>
  void for_each_neighbour_cell(const std::array<int, 3>& c, F&& f) const;

  const Coordinates& pos_;
  int dim_;
  double cutoff_;
  std::array<double, 3> lo_{}, length_{}, cell_size_{};
  std::array<int, 3> ncell_{1, 1, 1};
  std::array<bool, 3> periodic_{};
  std::vector<int> cell_start_;  // ncells + 1
  std::vector<int> order_;       // particle indices sorted by cell
};

template <class F>
void CellList::for_each_neighbour_cell(const std::array<int, 3>& c, F&& f) const {
  // Offsets per axis, deduplicated when a periodic axis has fewer than three cells so
  // that no cell (and so no pair) is visited twice.
  std::array<std::array<int, 3>, 3> cells{};
  std::array<int, 3> count{1, 1, 1};
  for (int a = 0; a < 3; ++a) {
    if (a >= dim_) {
      cells[a][0] = 0;
      continue;
    }
    int n = 0;
    for (int off = -1; off <= 1; ++off) {
      int k = c[a] + off;
      if (periodic_[a]) {
        k = (k + ncell_[a]) % ncell_[a];
      } else if (k < 0 || k >= ncell_[a]) {
        continue;
      }
      bool seen = false;
      for (int m = 0; m < n; ++m) seen = seen || cells[a][m] == k;
      if (!seen) cells[a][n++] = k;
    }
    count[a] = n;
  }
  for (int ix = 0; ix < count[0]; ++ix)
    for (int iy = 0; iy < count[1]; ++iy)
      for (int iz = 0; iz < count[2]; ++iz)
        f((cells[2][iz] * ncell_[1] + cells[1][iy]) * ncell_[0] + cells[0][ix]);
}

template <class F>
void CellList::for_each_pair(F&& f) const {
  // Each unordered pair of neighbouring cells once (the cell with the lower index visits
  // the other), so every particle pair is measured once.
  const double rc2 = cutoff_ * cutoff_;
  double d[3] = {0, 0, 0};
  auto visit = [&](int i, int j) {
    if (i > j) std::swap(i, j);
    double r2 = 0;
    for (int a = 0; a < dim_; ++a) d[a] = pos_(j, a) - pos_(i, a);
    minimum_image(d);
    for (int a = 0; a < dim_; ++a) r2 += d[a] * d[a];
    if (r2 <= rc2) f(i, j, static_cast<const double*>(d), r2);
  };
  std::array<int, 3> c{};
  for (c[2] = 0; c[2] < ncell_[2]; ++c[2])
    for (c[1] = 0; c[1] < ncell_[1]; ++c[1])
      for (c[0] = 0; c[0] < ncell_[0]; ++c[0]) {
        const int cell = (c[2] * ncell_[1] + c[1]) * ncell_[0] + c[0];
        const int begin = cell_start_[cell], end = cell_start_[cell + 1];
        if (begin == end) continue;
        for_each_neighbour_cell(c, [&](int other) {
          if (other < cell) return;
          if (other == cell) {
            for (int k = begin; k < end; ++k)
              for (int l = k + 1; l < end; ++l) visit(order_[k], order_[l]);
            return;
          }
          for (int k = begin; k < end; ++k)
            for (int l = cell_start_[other]; l < cell_start_[other + 1]; ++l)
              visit(order_[k], order_[l]);
        });
      }
}

template <class F>
void CellList::for_each_near(const double* x, double radius, F&& f) const {
  const double r2max = radius * radius;
  double d[3] = {0, 0, 0};
  std::array<int, 3> c{};
  cell_of(x, c);
  for_each_neighbour_cell(c, [&](int cell) {
    for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
      const int j = order_[k];
      double r2 = 0;
      for (int a = 0; a < dim_; ++a) d[a] = pos_(j, a) - x[a];
      minimum_image(d);
      for (int a = 0; a < dim_; ++a) r2 += d[a] * d[a];
      if (r2 <= r2max) f(j, static_cast<const double*>(d), r2);
    }
  });
}

}  // namespace granpipe
