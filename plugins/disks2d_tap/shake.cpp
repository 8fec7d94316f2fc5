#include "shake.hpp"

#include <cmath>
#include <numbers>

#include "granpipe/stop_request.hpp"

namespace granpipe::disks2d_tap {

void Shaker::tap(DiskPacking& p, double A, RandomStream& rng) {
  const std::size_t n = p.size();
  if (!(A > 1.0) || n == 0) return;
  const double r_min = p.min_radius(), r_max = p.max_radius();
  for (std::size_t i = 0; i < n; ++i) {
    p.y[i] = dilation_ == Dilation::CentreHeight ? A * p.y[i] : r_min + A * (p.y[i] - r_min);
  }
  p.clear_supports();

  const double jump = A - 1.0;
  // No disk can climb above the dilated top plus one jump per loop.
  const double cell = std::sqrt(2.0) * r_min * (1.0 - 1e-9);
  grid_.reset(p.width, p.top() + loops_ * jump + cell, cell, 2.0 * r_max);
  cell_.resize(n);
  order_.reset(n);
  for (std::size_t i = 0; i < n; ++i) {
    cell_[i] = grid_.cell_of(p.x[i], p.y[i]);
    grid_.put(static_cast<std::int32_t>(i), cell_[i]);
  }

  for (int loop = 0; loop < loops_; ++loop) {
    throw_if_stop_requested();  // a tap of a wide bed may take minutes
    for (const std::int32_t disk : order_.next(rng)) {
      const auto i = static_cast<std::size_t>(disk);
      const double length = jump * rng.uniform();
      const double angle = 2.0 * std::numbers::pi * rng.uniform();
      const double x = p.x[i] + length * std::cos(angle), y = p.y[i] + length * std::sin(angle);
      const double ri = p.r[i];
      ++stats_.trials;
      if (x - ri < 0.0 || x + ri > p.width || y - ri < 0.0) continue;
      bool overlap = false;
      const double reach = ri + r_max;
      grid_.for_each_in(x - reach, x + reach, y - reach, y + reach, [&](std::int32_t j) {
        const auto m = static_cast<std::size_t>(j);
        if (m == i) return;
        const double dx = p.x[m] - x, dy = p.y[m] - y, R = ri + p.r[m];
        overlap = overlap || dx * dx + dy * dy < R * R;
      });
      if (overlap) continue;
      ++stats_.accepted;
      p.x[i] = x;
      p.y[i] = y;
      const int c = grid_.cell_of(x, y);
      if (c != cell_[i]) {
        grid_.erase(cell_[i]);
        grid_.put(static_cast<std::int32_t>(i), c);
        cell_[i] = c;
      }
    }
  }
}

}  // namespace granpipe::disks2d_tap
