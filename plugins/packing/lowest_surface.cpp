#include "lowest_surface.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace granpipe::packing {

namespace {

// The columns along one horizontal axis: n equal intervals of [lo, hi].
struct Axis {
  double lo = 0.0, step = 1.0;
  long n = 1;
  Axis(double a, double b, double width)
      : lo(a), n(std::max(1L, static_cast<long>(std::floor((b - a) / width)))) {
    step = (b - a) / static_cast<double>(n);
  }
  // Columns whose open interval meets the open interval (x - r, x + r).
  long first(double x, double r) const {
    return std::max(0L, static_cast<long>(std::floor((x - r - lo) / step)));
  }
  long last(double x, double r) const {
    return std::min(n - 1, static_cast<long>(std::ceil((x + r - lo) / step)) - 1);
  }
  double column_lo(long k) const { return lo + static_cast<double>(k) * step; }
};

}  // namespace

double lowest_surface(const Frame& frame, const Region& columns, double width, double base) {
  const int dim = frame.dim, v = dim - 1;
  for (int a = 0; a < v; ++a) {
    if (!(columns.hi[a] > columns.lo[a])) return base;
  }
  const Container& c = frame.container;
  // Horizontal axes 0 and (in 3D) 1; the vertical axis is the last.
  const Axis ax(columns.lo[0], columns.hi[0], width);
  const Axis ay = dim == 3 ? Axis(columns.lo[1], columns.hi[1], width) : Axis(0.0, 1.0, 1.0);
  std::vector<double> top(static_cast<std::size_t>(ax.n * ay.n), base);
  std::vector<double> shifts_x, shifts_y{0.0};
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    const double r = frame.radius()[k], height = frame.position()(k, v) + r;
    image_shifts(frame.position()(k, 0), r, columns.lo[0], columns.hi[0], c.periodic(0),
                 c.length(0), shifts_x);
    if (dim == 3) {
      image_shifts(frame.position()(k, 1), r, columns.lo[1], columns.hi[1], c.periodic(1),
                   c.length(1), shifts_y);
    }
    for (const double sy : shifts_y) {
      for (const double sx : shifts_x) {
        const double x = frame.position()(k, 0) + sx;
        const double y = dim == 3 ? frame.position()(k, 1) + sy : 0.5;
        for (long i = ax.first(x, r); i <= ax.last(x, r); ++i) {
          for (long j = ay.first(y, r); j <= ay.last(y, r); ++j) {
            if (dim == 3) {
              // The disc meets the square column if its nearest point lies within r.
              const double nx = std::clamp(x, ax.column_lo(i), ax.column_lo(i + 1));
              const double ny = std::clamp(y, ay.column_lo(j), ay.column_lo(j + 1));
              if ((nx - x) * (nx - x) + (ny - y) * (ny - y) >= r * r) continue;
            }
            double& t = top[static_cast<std::size_t>(i * ay.n + j)];
            t = std::max(t, height);
          }
        }
      }
    }
  }
  return *std::min_element(top.begin(), top.end());
}

}  // namespace granpipe::packing
