#include "granpipe/cut_profile.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "granpipe/overlap.hpp"

namespace granpipe {
namespace {

// The periodic images of one particle that reach the region across its extent along the
// axes other than `axis` and the range [x0, x1] along it, one call per image: `at` holds
// the image's centre.
template <class Visit>
void for_each_image(const Frame& frame, Eigen::Index k, const Region& region, int axis, double x0,
                    double x1, Visit&& visit) {
  const Container& c = frame.container;
  const double r = frame.radius()[k];
  std::array<std::vector<double>, 3> shifts;
  for (int a = 0; a < frame.dim; ++a) {
    const double lo = a == axis ? x0 : region.lo[a], hi = a == axis ? x1 : region.hi[a];
    image_shifts(frame.position()(k, a), r, lo, hi, c.periodic(a), c.length(a), shifts[a]);
    if (shifts[a].empty()) return;
  }
  if (frame.dim == 2) shifts[2].assign(1, 0.0);
  std::array<double, 3> at{0.0, 0.0, 0.0};
  for (double s2 : shifts[2])
    for (double s1 : shifts[1])
      for (double s0 : shifts[0]) {
        at[0] = frame.position()(k, 0) + s0;
        at[1] = frame.position()(k, 1) + s1;
        if (frame.dim == 3) at[2] = frame.position()(k, 2) + s2;
        visit(at);
      }
}

// The cuts at x0 + (k + 1/2) step that [x - r, x + r] reaches.
std::pair<int, int> cuts_reached(double x, double r, double x0, double step, int count) {
  return {std::max(0, static_cast<int>(std::ceil((x - r - x0) / step - 0.5))),
          std::min(count - 1, static_cast<int>(std::floor((x + r - x0) / step - 0.5)))};
}

// The bins [x0 + k step, x0 + (k + 1) step) that [x - r, x + r] reaches.
std::pair<int, int> bins_reached(double x, double r, double x0, double step, int count) {
  return {std::max(0, static_cast<int>(std::floor((x - r - x0) / step))),
          std::min(count - 1, static_cast<int>(std::floor((x + r - x0) / step)))};
}

// Area of the section (radius w, centre `at`) within the region's extent along the other
// axes: a chord length in 2D, a disc area in 3D.
double section_in(int dim, const std::array<double, 3>& at, double w, const Region& region,
                  int axis) {
  if (dim == 2) {
    const int o = 1 - axis;
    return overlap::interval_overlap(at[o], w, region.lo[o], region.hi[o]);
  }
  const int p = axis == 0 ? 1 : 0, q = axis == 2 ? 1 : 2;
  return overlap::disk_rectangle_area(Eigen::Vector2d(at[p], at[q]), w,
                                      Eigen::Vector2d(region.lo[p], region.lo[q]),
                                      Eigen::Vector2d(region.hi[p], region.hi[q]));
}

// The region's measure across `axis`: its width (2D) or cross-section area (3D).
double cross_section(int dim, const Region& region, int axis) {
  double s = 1.0;
  for (int a = 0; a < dim; ++a)
    if (a != axis) s *= region.hi[a] - region.lo[a];
  return s;
}

// Whether the particle at `at` lies within the region's extent along every axis but `axis`.
bool inside_across(int dim, const std::array<double, 3>& at, double r, const Region& region,
                   int axis) {
  for (int a = 0; a < dim; ++a) {
    if (a != axis && (at[a] - r < region.lo[a] || at[a] + r > region.hi[a])) return false;
  }
  return true;
}

// Measure of the part of a ball (2D: disk) between a and b along one axis, the ball whole
// across: a difference of caps (segments).
double slab_measure(int dim, double r, double a, double b) {
  return dim == 3 ? overlap::sphere_cap_volume(r, a) - overlap::sphere_cap_volume(r, b)
                  : overlap::disk_segment_area(r, a) - overlap::disk_segment_area(r, b);
}

// What `add(at, r, sum)` puts into the slots of `sum` for every image (centre `at`, radius r)
// of every particle that reaches the range [x0, x0 + step count) along `axis`, over `norm`.
template <class Add>
std::vector<double> summed_over_images(const Frame& frame, const Region& region, int axis,
                                       double x0, double step, int count, double norm, Add&& add) {
  std::vector<double> sum(static_cast<std::size_t>(std::max(count, 0)), 0.0);
  if (count <= 0) return sum;
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    const double r = frame.radius()[k];
    for_each_image(frame, k, region, axis, x0, x0 + step * count,
                   [&](const auto& at) { add(at, r, sum); });
  }
  for (double& s : sum) s /= norm;
  return sum;
}

}  // namespace

std::vector<double> cut_fractions(const Frame& frame, const Region& region, int axis, double x0,
                                  double step, int count) {
  const int dim = frame.dim;
  return summed_over_images(
      frame, region, axis, x0, step, count, cross_section(dim, region, axis),
      [&](const std::array<double, 3>& at, double r, std::vector<double>& sum) {
        const auto [first, last] = cuts_reached(at[axis], r, x0, step, count);
        for (int m = first; m <= last; ++m) {
          const double w = overlap::cut_radius(r, x0 + (m + 0.5) * step - at[axis]);
          if (w > 0.0) sum[static_cast<std::size_t>(m)] += section_in(dim, at, w, region, axis);
        }
      });
}

std::vector<double> bin_fractions(const Frame& frame, const Region& region, int axis, double x0,
                                  double step, int count) {
  const int dim = frame.dim;
  return summed_over_images(
      frame, region, axis, x0, step, count, cross_section(dim, region, axis) * step,
      [&](const std::array<double, 3>& at, double r, std::vector<double>& sum) {
        const auto [first, last] = bins_reached(at[axis], r, x0, step, count);
        const bool whole_across = inside_across(dim, at, r, region, axis);
        Region bin = region;
        for (int m = first; m <= last; ++m) {
          bin.lo[axis] = x0 + m * step;
          bin.hi[axis] = x0 + (m + 1) * step;
          sum[static_cast<std::size_t>(m)] +=
              whole_across
                  ? slab_measure(dim, r, bin.lo[axis] - at[axis], bin.hi[axis] - at[axis])
                  : overlap::ball_box_measure(dim, at.data(), r, bin.lo.data(), bin.hi.data());
        }
      });
}

}  // namespace granpipe
