#include "granpipe/region.hpp"

#include <cmath>

#include "granpipe/overlap.hpp"

namespace granpipe {

double Region::volume() const {
  double v = 1.0;
  for (int a = 0; a < dim; ++a) v *= hi[a] - lo[a];
  return v;
}

Region container_region(const Frame& frame) {
  Region r;
  r.dim = frame.dim;
  for (int a = 0; a < 3; ++a) {
    r.lo[a] = frame.container.wall_at(a, 0);
    r.hi[a] = frame.container.wall_at(a, 1);
  }
  return r;
}

void image_shifts(double x, double r, double a, double b, bool periodic, double period,
                  std::vector<double>& out) {
  out.clear();
  if (!periodic) {
    if (x + r > a && x - r < b) out.push_back(0.0);
    return;
  }
  // x + kL + r > a and x + kL - r < b.
  const auto kmin = static_cast<long>(std::floor((a - r - x) / period)) + 1;
  const auto kmax = static_cast<long>(std::ceil((b + r - x) / period)) - 1;
  for (long k = kmin; k <= kmax; ++k) out.push_back(static_cast<double>(k) * period);
}

double particle_measure_in(const Frame& frame, const Region& region) {
  const int dim = frame.dim;
  const Container& c = frame.container;
  std::vector<double> shifts[3];
  double sum = 0.0;
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    const double r = frame.radius()[k];
    bool any = true;
    for (int a = 0; a < dim; ++a) {
      image_shifts(frame.position()(k, a), r, region.lo[a], region.hi[a], c.periodic(a),
                   c.length(a), shifts[a]);
      any = any && !shifts[a].empty();
    }
    if (!any) continue;
    if (dim == 2) shifts[2].assign(1, 0.0);
    double x[3] = {0, 0, 0};
    for (double sz : shifts[2])
      for (double sy : shifts[1])
        for (double sx : shifts[0]) {
          x[0] = frame.position()(k, 0) + sx;
          x[1] = frame.position()(k, 1) + sy;
          if (dim == 3) x[2] = frame.position()(k, 2) + sz;
          sum += overlap::ball_box_measure(dim, x, r, region.lo.data(), region.hi.data());
        }
  }
  return sum;
}

std::vector<char> centres_in(const Frame& frame, const Region& region) {
  const Container& c = frame.container;
  std::vector<char> in(static_cast<std::size_t>(frame.size()), 0);
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    bool inside = true;
    for (int a = 0; a < frame.dim && inside; ++a) {
      const double x = c.wrap(a, frame.position()(k, a));
      inside = region.lo[a] <= x && x < region.hi[a];
    }
    in[static_cast<std::size_t>(k)] = inside;
  }
  return in;
}

}  // namespace granpipe
