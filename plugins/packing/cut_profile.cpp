#include "cut_profile.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/overlap.hpp"

namespace granpipe::packing {

std::vector<double> cut_fractions(const Frame& frame, const Region& lateral, double y0, double step,
                                  int count) {
  std::vector<double> sum(static_cast<std::size_t>(std::max(count, 0)), 0.0);
  if (count <= 0) return sum;
  const int dim = frame.dim, v = dim - 1;
  const Container& c = frame.container;
  const double y1 = y0 + step * count;
  std::vector<double> vertical, shifts[2];
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    const double r = frame.radius()[k];
    bool any = true;
    for (int a = 0; a < v; ++a) {
      image_shifts(frame.position()(k, a), r, lateral.lo[a], lateral.hi[a], c.periodic(a),
                   c.length(a), shifts[a]);
      any = any && !shifts[a].empty();
    }
    image_shifts(frame.position()(k, v), r, y0, y1, c.periodic(v), c.length(v), vertical);
    if (!any || vertical.empty()) continue;
    if (dim == 2) shifts[1].assign(1, 0.0);
    for (double sv : vertical) {
      const double yc = frame.position()(k, v) + sv;
      // Cuts whose height (k + 1/2) step lies within the particle.
      const int first = std::max(0, static_cast<int>(std::ceil((yc - r - y0) / step - 0.5)));
      const int last =
          std::min(count - 1, static_cast<int>(std::floor((yc + r - y0) / step - 0.5)));
      for (int m = first; m <= last; ++m) {
        const double w = overlap::cut_radius(r, y0 + (m + 0.5) * step - yc);
        if (w == 0.0) continue;
        double cut = 0.0;
        for (double s1 : shifts[1])
          for (double s0 : shifts[0]) {
            if (dim == 2) {
              cut += overlap::interval_overlap(frame.position()(k, 0) + s0, w, lateral.lo[0],
                                               lateral.hi[0]);
            } else {
              const Eigen::Vector2d centre(frame.position()(k, 0) + s0,
                                           frame.position()(k, 1) + s1);
              cut += overlap::disk_rectangle_area(centre, w, lateral.lo.head<2>(),
                                                  lateral.hi.head<2>());
            }
          }
        sum[static_cast<std::size_t>(m)] += cut;
      }
    }
  }
  double width = 1.0;
  for (int a = 0; a < v; ++a) width *= lateral.hi[a] - lateral.lo[a];
  for (double& s : sum) s /= width;
  return sum;
}

}  // namespace granpipe::packing
