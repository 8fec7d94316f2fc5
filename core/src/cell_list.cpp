#include "granpipe/cell_list.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/errors.hpp"

namespace granpipe {
namespace {
// Enough cells to be fast, few enough that a sparse, tall system does not allocate
// a huge grid: cells beyond this are merged (each cell gets larger than the cutoff).
constexpr long kMaxCells = 1 << 22;
}  // namespace

CellList::CellList(const Coordinates& position, const Container& container, int dim,
                   double cutoff)
    : pos_(position), dim_(dim), cutoff_(cutoff) {
  if (!(cutoff > 0) || !std::isfinite(cutoff)) {
    throw InternalError("CellList: cutoff must be finite and > 0");
  }
  const Eigen::Index n = position.rows();
  for (int a = 0; a < dim; ++a) {
    periodic_[a] = container.periodic(a);
    if (periodic_[a]) {
      lo_[a] = container.lo[a];
      length_[a] = container.length(a);
      if (length_[a] < 2 * cutoff) {
        throw InputError("neighbour search: periodic box length " + std::to_string(length_[a]) +
                         " along axis " + std::to_string(a) +
                         " is shorter than twice the interaction range " +
                         std::to_string(cutoff));
      }
    } else {
      // Non-periodic axes span the particles (they may leave an open top).
      double mn = n ? position.col(a).minCoeff() : 0.0, mx = n ? position.col(a).maxCoeff() : 0.0;
      lo_[a] = mn;
      length_[a] = std::max(mx - mn, cutoff);
    }
  }
  long total = 1;
  for (int a = 0; a < dim; ++a) {
    ncell_[a] = std::max(1, static_cast<int>(std::floor(length_[a] / cutoff)));
    total *= ncell_[a];
  }
  while (total > kMaxCells) {
    total = 1;
    for (int a = 0; a < dim; ++a) {
      ncell_[a] = std::max(1, ncell_[a] / 2);
      total *= ncell_[a];
    }
  }
  for (int a = 0; a < dim; ++a) cell_size_[a] = length_[a] / ncell_[a];

  // Counting sort of particles by cell.
  std::vector<int> cell(n);
  cell_start_.assign(total + 1, 0);
  std::array<int, 3> c{};
  double x[3] = {0, 0, 0};
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int a = 0; a < dim; ++a) x[a] = position(i, a);
    cell[i] = cell_of(x, c);
    ++cell_start_[cell[i] + 1];
  }
  for (long k = 0; k < total; ++k) cell_start_[k + 1] += cell_start_[k];
  order_.resize(n);
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (Eigen::Index i = 0; i < n; ++i) order_[fill[cell[i]]++] = static_cast<int>(i);
}

int CellList::cell_of(const double* x, std::array<int, 3>& c) const {
  for (int a = 0; a < 3; ++a) {
    if (a >= dim_) {
      c[a] = 0;
      continue;
    }
    double u = (x[a] - lo_[a]) / cell_size_[a];
    int k = static_cast<int>(std::floor(u));
    if (periodic_[a]) {
      k %= ncell_[a];
      if (k < 0) k += ncell_[a];
    } else {
      k = std::clamp(k, 0, ncell_[a] - 1);
    }
    c[a] = k;
  }
  return (c[2] * ncell_[1] + c[1]) * ncell_[0] + c[0];
}

void CellList::minimum_image(double* d) const {
  for (int a = 0; a < dim_; ++a) {
    if (periodic_[a]) d[a] -= length_[a] * std::round(d[a] / length_[a]);
  }
}

}  // namespace granpipe
