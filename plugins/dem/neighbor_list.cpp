#include "neighbor_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granpipe::dem {

namespace {

// The 13 neighbour cells after a cell in z-major order (dz, dy, dx): with the cell itself
// they hold every later particle a small particle can touch.
constexpr int kForward[13][3] = {{0, 0, 1},  {0, 1, -1}, {0, 1, 0},  {0, 1, 1}, {1, -1, -1},
                                 {1, -1, 0}, {1, -1, 1}, {1, 0, -1}, {1, 0, 0}, {1, 0, 1},
                                 {1, 1, -1}, {1, 1, 0},  {1, 1, 1}};
// Particles larger than this many median radii search for their own partners.
constexpr double kBigOverMedian = 1.5;
// The force loop's work, relative to that of a listed pair: per particle (damping, walls)
// and per pair in contact (its force). Measured on the Brazil-nut scene (CPU time of each
// of two threads); the work of the pairs in contact at the build stands for that of the
// steps after it.
constexpr double kParticleWork = 2.0;
constexpr double kContactWork = 6.0;

}  // namespace

NeighborList::NeighborList(double skin, int reaction_stride, bool history, bool rolling_history)
    : reaction_stride(reaction_stride),
      skin_(skin),
      keep_history_(history),
      keep_rolling_history_(rolling_history) {}

int NeighborList::Grid::cell_of(const double* x) const {
  int c[3];
  for (int a = 0; a < 3; ++a) {
    // Written so that a NaN lands in cell 0 and an infinity in the last cell: a blown-up
    // particle must not make the grid index undefined (the caller reports the blow-up).
    double t = (x[a] - lo[a]) * inv_cell;
    if (!(t >= 0.0)) t = 0.0;
    if (t > n[a] - 1) t = n[a] - 1;
    c[a] = static_cast<int>(t);
  }
  return (c[2] * n[1] + c[1]) * n[0] + c[0];
}

void NeighborList::size_grid(const Particles& p) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (int i = 0; i < p.size(); ++i) {
    if (!p.x.col(i).allFinite()) continue;
    lo = lo.cwiseMin(p.x.col(i));
    hi = hi.cwiseMax(p.x.col(i));
  }
  if (!(lo.array() <= hi.array()).all()) lo = hi = Eigen::Vector3d::Zero();
  grid_.lo = lo;
  grid_.cell = 2.0 * split_radius_ + skin_;
  // Far-flung particles must not make the grid huge: at most a few cells per particle.
  const double max_cells = 4.0 * p.size() + 64.0;
  for (;;) {
    double cells = 1.0;
    for (int a = 0; a < 3; ++a) cells *= std::floor((hi[a] - lo[a]) / grid_.cell) + 1.0;
    if (cells <= max_cells) break;
    grid_.cell *= 1.25;
  }
  grid_.inv_cell = 1.0 / grid_.cell;
  for (int a = 0; a < 3; ++a) {
    grid_.n[a] = static_cast<int>(std::floor((hi[a] - lo[a]) * grid_.inv_cell)) + 1;
  }
}

void NeighborList::sort_by_cell(Particles& p) {
  const int n = p.size(), ncell = grid_.count();
  cell_of_.resize(static_cast<std::size_t>(n));
  cell_start_.assign(static_cast<std::size_t>(ncell) + 1, 0);
  for (int i = 0; i < n; ++i) {
    cell_of_[i] = grid_.cell_of(&p.x(0, i));
    ++cell_start_[cell_of_[i] + 1];
  }
  for (int c = 0; c < ncell; ++c) cell_start_[c + 1] += cell_start_[c];
  order_.resize(static_cast<std::size_t>(n));
  count_.assign(cell_start_.begin(), cell_start_.end() - 1);  // fill cursors per cell
  for (int i = 0; i < n; ++i) order_[count_[cell_of_[i]]++] = i;
  p.permute(order_);
  // After the permutation the particles of cell c are cell_start_[c] .. cell_start_[c+1]-1.
  for (int c = 0; c < ncell; ++c) {
    for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) cell_of_[k] = c;
  }
}

template <class F>
void NeighborList::for_each_candidate(const Particles& p, int i, F&& f) const {
  const int nx = grid_.n[0], ny = grid_.n[1], nz = grid_.n[2];
  const int c = cell_of_[i];
  const int cx = c % nx, cy = (c / nx) % ny, cz = c / (nx * ny);
  if (!big_[i]) {
    for (int j = i + 1; j < cell_start_[c + 1]; ++j) {
      if (!big_[j]) f(j);
    }
    for (const auto& o : kForward) {
      const int x = cx + o[2], y = cy + o[1], z = cz + o[0];
      if (x < 0 || x >= nx || y < 0 || y >= ny || z >= nz) continue;
      const int d = (z * ny + y) * nx + x;
      for (int j = cell_start_[d]; j < cell_start_[d + 1]; ++j) {
        if (!big_[j]) f(j);
      }
    }
    return;
  }
  // A big particle lists all its partners, small ones and later big ones.
  const int m = static_cast<int>(std::ceil((p.radius[i] + max_radius_ + skin_) * grid_.inv_cell));
  for (int z = std::max(cz - m, 0); z <= std::min(cz + m, nz - 1); ++z) {
    for (int y = std::max(cy - m, 0); y <= std::min(cy + m, ny - 1); ++y) {
      const int row = (z * ny + y) * nx;
      const int d0 = row + std::max(cx - m, 0), d1 = row + std::min(cx + m, nx - 1);
      for (int j = cell_start_[d0]; j < cell_start_[d1 + 1]; ++j) {
        if (j != i && (!big_[j] || j > i)) f(j);
      }
    }
  }
}

void NeighborList::list_pairs(const Particles& p, int threads) {
  const int n = p.size();
  first.assign(static_cast<std::size_t>(n) + 1, 0);
  const double* x = p.x.data();
  const double* r = p.radius.data();
  const auto near = [&](int i, int j) {
    const double dx = x[3 * i] - x[3 * j], dy = x[3 * i + 1] - x[3 * j + 1],
                 dz = x[3 * i + 2] - x[3 * j + 2];
    const double reach = r[i] + r[j] + skin_;
    return dx * dx + dy * dy + dz * dz < reach * reach;
  };
  const auto in_contact = [&](int i, int j) {
    const double dx = x[3 * i] - x[3 * j], dy = x[3 * i + 1] - x[3 * j + 1],
                 dz = x[3 * i + 2] - x[3 * j + 2];
    return dx * dx + dy * dy + dz * dz < (r[i] + r[j]) * (r[i] + r[j]);
  };
#pragma omp parallel for schedule(dynamic, 128) num_threads(threads)
  for (int i = 0; i < n; ++i) {
    int count = 0;
    for_each_candidate(p, i, [&](int j) { count += near(i, j); });
    first[i + 1] = count;
  }
  for (int i = 0; i < n; ++i) first[i + 1] += first[i];
  partner.resize(static_cast<std::size_t>(first[n]));
  owner.resize(partner.size());
  work_before.assign(static_cast<std::size_t>(n) + 1, 0.0);
#pragma omp parallel for schedule(dynamic, 128) num_threads(threads)
  for (int i = 0; i < n; ++i) {
    int k = first[i], touching = 0;
    for_each_candidate(p, i, [&](int j) {
      if (!near(i, j)) return;
      partner[k++] = j;
      touching += in_contact(i, j);
    });
    std::fill(owner.begin() + first[i], owner.begin() + k, i);
    work_before[i + 1] = kParticleWork + (k - first[i]) + kContactWork * touching;
  }
  for (int i = 0; i < n; ++i) work_before[i + 1] += work_before[i];
}

void NeighborList::restore_history(const PairHistory& saved, HugePageVector<double>& to,
                                   const Particles& p, int threads) {
  const int n = p.size();
  to.resize(3 * partner.size());
#pragma omp parallel for schedule(dynamic, 128) num_threads(threads)
  for (int i = 0; i < n; ++i) {
    for (int k = first[i]; k < first[i + 1]; ++k) {
      saved.find(p.tag[i], p.tag[partner[k]], &to[3 * static_cast<std::size_t>(k)]);
    }
  }
}

void NeighborList::index_reverse(int n) {
  reverse_first.assign(static_cast<std::size_t>(n) + 1, 0);
  for (std::int32_t j : partner) ++reverse_first[j + 1];
  for (int i = 0; i < n; ++i) reverse_first[i + 1] += reverse_first[i];
  reaction_slot.resize(partner.size());
  count_.assign(reverse_first.begin(), reverse_first.end() - 1);
  for (std::size_t k = 0; k < partner.size(); ++k) reaction_slot[k] = count_[partner[k]]++;
}

void NeighborList::rebuild(Particles& p, int threads) {
  const int n = p.size();
  if (keep_history_) saved_.save(first, partner, history, p.tag);
  if (keep_rolling_history_) saved_rolling_.save(first, partner, rolling_history, p.tag);
  if (builds_ == 0 && n > 0) {
    std::vector<double> r(p.radius.data(), p.radius.data() + n);
    std::nth_element(r.begin(), r.begin() + n / 2, r.end());
    const double median = r[n / 2];
    max_radius_ = p.radius.maxCoeff();
    split_radius_ = 0.0;
    for (int i = 0; i < n; ++i) {
      if (p.radius[i] <= kBigOverMedian * median)
        split_radius_ = std::max(split_radius_, p.radius[i]);
    }
  }
  size_grid(p);
  sort_by_cell(p);
  big_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) big_[i] = p.radius[i] > split_radius_;
  list_pairs(p, threads);
  if (keep_history_) restore_history(saved_, history, p, threads);
  if (keep_rolling_history_) restore_history(saved_rolling_, rolling_history, p, threads);
  incoming.assign(static_cast<std::size_t>(reaction_stride) * partner.size(), 0.0);
  index_reverse(n);
  if (x_build_.cols() != p.x.cols()) {
    x_build_.resize(3, p.x.cols());
    huge_pages::advise(x_build_.data(), static_cast<std::size_t>(x_build_.size()) * sizeof(double));
  }
  x_build_ = p.x;
  ++builds_;
}

}  // namespace granpipe::dem
