#include "granpipe/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {
namespace {
// Enough cells to be fast, few enough that a sparse, tall system does not allocate
// a huge grid: cells beyond this are merged (each cell gets larger than the cutoff).
constexpr double kMaxCells = 1 << 22;
// Beyond this many contact ranges per box length, positions carry fewer than 7
// significant digits at the particles' scale (doubles have 16): an infinite box or a
// radius of 1e-200 is nonsense to measure, not a packing.
constexpr double kMaxLengthInRanges = 1e9;
// Squared distances must stay normal doubles (from about 1e-308 to 1e308).
constexpr double kMinRange = 1e-100, kMaxRange = 1e100;

const char* axis_name(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }

}  // namespace

CellList::CellList(const Coordinates& position, const Container& container, int dim, double cutoff,
                   const std::string& where)
    : pos_(position), dim_(dim), cutoff_(cutoff) {
  const std::string at = (where.empty() ? "" : where + ": ") + "neighbour search: ";
  if (!(cutoff >= kMinRange && cutoff <= kMaxRange)) {
    throw InputError(at + "expected a contact range (largest contact distance) from " +
                     format_number(kMinRange) + " to " + format_number(kMaxRange) + ", got " +
                     format_number(cutoff));
  }
  const Eigen::Index n = position.rows();
  for (int a = 0; a < dim; ++a) {
    periodic_[a] = container.periodic(a);
    if (periodic_[a]) {
      lo_[a] = container.lo[a];
      length_[a] = container.length(a);
      if (!(length_[a] >= 2 * cutoff)) {
        throw InputError(at + "expected a periodic box of length at least " +
                         format_apart(2 * cutoff, length_[a]) +
                         " (twice the contact range) along " + axis_name(a) + ", got " +
                         format_apart(length_[a], 2 * cutoff));
      }
    } else {
      // Non-periodic axes span the particles (they may leave an open top).
      double mn = n ? position.col(a).minCoeff() : 0.0, mx = n ? position.col(a).maxCoeff() : 0.0;
      lo_[a] = mn;
      length_[a] = std::max(mx - mn, cutoff);
    }
    if (!(length_[a] <= kMaxLengthInRanges * cutoff)) {
      throw InputError(at + "expected a box at most " + format_number(kMaxLengthInRanges) +
                       " contact ranges (" + format_number(cutoff) + ") long along " +
                       axis_name(a) + ", got " +
                       (periodic_[a] ? "a periodic box of length " : "particles spread over ") +
                       format_number(length_[a]));
    }
  }
  // Cells per axis, estimated in double (their product could overflow an integer).
  std::array<double, 3> cells{1, 1, 1};
  double total = 1;
  for (int a = 0; a < dim; ++a) {
    cells[a] = std::max(1.0, std::floor(length_[a] / cutoff));
    total *= cells[a];
  }
  while (total > kMaxCells) {
    total = 1;
    for (int a = 0; a < dim; ++a) {
      cells[a] = std::max(1.0, std::floor(cells[a] / 2));
      total *= cells[a];
    }
  }
  for (int a = 0; a < dim; ++a) {
    ncell_[a] = static_cast<int>(cells[a]);
    cell_size_[a] = length_[a] / ncell_[a];
  }
  const long ncells = static_cast<long>(total);

  // Counting sort of particles by cell.
  std::vector<int> cell(n);
  cell_start_.assign(ncells + 1, 0);
  std::array<int, 3> c{};
  double x[3] = {0, 0, 0};
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int a = 0; a < dim; ++a) x[a] = position(i, a);
    cell[i] = cell_of(x, c);
    ++cell_start_[cell[i] + 1];
  }
  for (long k = 0; k < ncells; ++k) cell_start_[k + 1] += cell_start_[k];
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
