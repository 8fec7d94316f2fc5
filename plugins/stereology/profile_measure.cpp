#include "profile_measure.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/bin_count.hpp"
#include "granpipe/cut_profile.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/region.hpp"

namespace granpipe::stereology {
namespace {

double highest_top(const Frame& f) { return (f.position().col(f.dim - 1) + f.radius()).maxCoeff(); }

std::vector<double> bin_heights(std::size_t count, double step) {
  std::vector<double> z(count);
  for (std::size_t k = 0; k < count; ++k) z[k] = (static_cast<double>(k) + 0.5) * step;
  return z;
}

// Lateral and central fractions of the heights 0..H, across x. A central zone narrower
// than `narrowest` is none: the fraction of a slab 1e-10 R wide is the rounding of the cuts
// around it (0.05 for 0.52, exit 0).
void measure_zones(const Frame& f, const Region& zone, double band, double narrowest,
                   ProfileMeasurement& m) {
  const double lo = zone.lo[0], hi = zone.hi[0];
  const double near_low = bin_fractions(f, zone, 0, lo, band, 1)[0];
  const double near_high = bin_fractions(f, zone, 0, hi - band, band, 1)[0];
  m.lateral = 0.5 * (near_low + near_high);
  const double central = hi - lo - 2.0 * band;
  m.central =
      central >= narrowest ? bin_fractions(f, zone, 0, lo + band, central, 1)[0] : std::nan("");
}

}  // namespace

ProfileMeasurement measure_profiles(const Frame& frame, const ProfileSettings& s) {
  if (frame.size() == 0) throw InputError("stereology: the frame has no particles");
  ProfileMeasurement m;
  m.global = global_fractions(frame, s.global);
  const int v = frame.dim - 1;
  const double r = m.global.radius, base = frame.container.wall_at(v, 0);
  const Region box = container_region(frame);

  const double step = s.step * r;
  check_bin_count((highest_top(frame) - base) / r, s.step, s.params + ".step",
                  "bins of the vertical profile");
  check_step_fits((highest_top(frame) - base) / r, s.step, s.params + ".step",
                  "the bed's height in radii");
  const int count = std::max(1, static_cast<int>(std::ceil((highest_top(frame) - base) / step)));
  m.vertical = bin_fractions(frame, box, v, base, step, count);

  Region zone = box;
  zone.hi[v] = base + m.global.height_c;
  const double width = box.hi[0] - box.lo[0];
  check_bin_count(width / r, s.step, s.params + ".step", "bins of the transversal profile");
  check_step_fits(width / r, s.step, s.params + ".step", "the box's width in radii");
  const int across = std::max(1, static_cast<int>(std::lround(width / step)));
  m.transversal_step = width / across / r;
  m.transversal = bin_fractions(frame, zone, 0, box.lo[0], width / across, across);
  measure_zones(frame, zone, std::min(s.lateral_band * r, 0.5 * width), kNarrowestZone * r, m);

  m.fit = fit_fermi_profile(bin_heights(m.vertical.size(), s.step), m.vertical, s.fit_from);
  return m;
}

}  // namespace granpipe::stereology
