#include "granpipe/stereology.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "granpipe/bottom_wall.hpp"
#include "granpipe/cut_profile.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/region.hpp"

namespace granpipe {
namespace {

// The mean cut fraction between heights a and b above the bottom (one exact bin).
double fraction_between(const Frame& frame, const Region& cross, double a, double b) {
  const int v = frame.dim - 1;
  const double base = frame.container.wall_at(v, 0);
  return bin_fractions(frame, cross, v, base + a, b - a, 1)[0];
}

// The height above the bottom below which `fraction` of the centres lie (the smallest
// centre height with at least that share of centres at or below it).
double quantile_height(const Frame& frame, double fraction) {
  const int v = frame.dim - 1;
  std::vector<double> z(frame.position().col(v).begin(), frame.position().col(v).end());
  const auto n = static_cast<double>(z.size());
  // A share that is a whole number of centres counts it whole: 0.14 * 50 is
  // 7.000000000000001 in doubles, and took the 8th centre.
  const double share = fraction * n;
  const double centres = std::ceil(share - 64.0 * std::numeric_limits<double>::epsilon() * share);
  const auto k = static_cast<std::size_t>(std::max(0.0, centres - 1.0));
  std::nth_element(z.begin(), z.begin() + static_cast<long>(k), z.end());
  return z[k] - frame.container.wall_at(v, 0);
}

// A centre beyond an open lateral side lies outside the cuts' cross-section: it was left out
// of phi while H and <Z> counted it (exit 0). Walls and periodic sides bound the bed anyway.
void refuse_centres_beyond_open_sides(const Frame& frame) {
  const Container& c = frame.container;
  for (int a = 0; a + 1 < frame.dim; ++a) {
    for (Eigen::Index i = 0; i < frame.size(); ++i) {
      const double x = frame.position()(i, a);
      const bool beyond = (c.boundary[a][0] == Boundary::Open && x < c.lo[a]) ||
                          (c.boundary[a][1] == Boundary::Open && x > c.hi[a]);
      if (!beyond) continue;
      throw InputError("particle " + std::to_string(i) + ": expected its centre within the open " +
                       "sides along " + "xyz"[a] + " (" + format_number(c.lo[a]) + " to " +
                       format_number(c.hi[a]) + "), where the cuts are, got " + format_number(x));
    }
  }
}

// The perturbed-zone model's factor for spheres near a plane (the paper's ref. [20]).
constexpr double kSpheresOnAPlane = 16.0 / 11.0;

// The bottom layer's correction for this frame: the one given, or for 0 the paper's.
double perturbed_factor(const Frame& frame, const StereologySettings& s) {
  if (s.perturbed_factor > 0.0) return s.perturbed_factor;
  if (frame.dim == 3) return kSpheresOnAPlane;
  throw InputError(s.factor_name +
                   ": expected a factor for disks (the paper's 16/11 is for spheres on a plane; "
                   "1: no correction), got 0 (the paper's value, which has none for disks)");
}

}  // namespace

void declare_stereology_settings(Schema& s) {
  const StereologySettings d;
  s.real("bulk_top", d.bulk_top, "phi_b is the packing fraction between the bottom and this height")
      .min(0.0, true)
      .unit("mean radii");
  s.real("perturbed_top", d.perturbed_top,
         "top of the bottom layer perturbed by the wall, whose fraction phi_c corrects")
      .min(0.0)
      .unit("mean radii");
  s.real("perturbed_factor", d.perturbed_factor,
         "phi_c multiplies the bottom layer's fraction by this; 0: the perturbed-zone "
         "model's 16/11 for spheres on a plane (the paper gives none for disks: 2D frames "
         "need a factor given); 1: no correction")
      .min(0.0)
      .only_where("perturbed_top > 0",
                  [](const Params& p) { return p.real("perturbed_top") > 0.0; });
  s.real("fraction", d.fraction,
         "phi_c's zone reaches the height below which this fraction of the centres lie")
      .min(0.0, true)
      .max(1.0);
}

StereologySettings stereology_settings(const Params& p, std::string factor_name) {
  return {p.real("bulk_top"), p.real("perturbed_top"), p.real("perturbed_factor"),
          p.real("fraction"), std::move(factor_name)};
}

GlobalFractions global_fractions(const Frame& frame, const StereologySettings& s) {
  if (frame.container.shape != ContainerShape::Box) {
    throw InputError(
        "expected a box container (cuts need a rectangular "
        "cross-section), got a cylinder");
  }
  const int v = frame.dim - 1;
  // (Periodic along the vertical, phi_c of a crystal came out above the crystal's fraction
  // by the correction of a layer no wall perturbs, exit 0.)
  require_bottom_wall(frame.container, v,
                      std::string("expected a container with a bottom wall along ") + "xyz"[v] +
                          " (heights are above it; phi_c corrects the layer it perturbs)");
  refuse_centres_beyond_open_sides(frame);
  // Without a layer there is nothing to correct, and disks need no factor.
  const double factor = s.perturbed_top > 0.0 ? perturbed_factor(frame, s) : 1.0;
  GlobalFractions g;
  g.phi_b = g.phi_c = std::nan("");
  if (frame.size() == 0) return g;
  g.radius = frame.radius().mean();
  const Region cross = container_region(frame);
  const double r = g.radius;
  g.top = (frame.position().col(v) + frame.radius()).maxCoeff() - frame.container.wall_at(v, 0);
  if (s.bulk_top * r <= g.top) g.phi_b = fraction_between(frame, cross, 0.0, s.bulk_top * r);
  g.height_c = quantile_height(frame, s.fraction);
  const double layer = s.perturbed_top * r, h = g.height_c;
  if (h > layer) {
    // An empty layer (perturbed_top 0: no correction) has no fraction of its own.
    const double corrected =
        layer > 0.0 ? factor * fraction_between(frame, cross, 0.0, layer) : 0.0;
    // A layer more than full is no packing (a factor of 1e300 gave phi_c 1.9e298, exit 0).
    if (corrected > 1.0) {
      throw InputError(s.factor_name +
                       ": expected a correction that leaves the bottom layer's fraction at most "
                       "1, got " +
                       format_number(factor) + ", which makes it " + format_number(corrected));
    }
    g.phi_c = (corrected * layer + fraction_between(frame, cross, layer, h) * (h - layer)) / h;
  }
  return g;
}

std::string undefined_fractions(const GlobalFractions& g, const StereologySettings& s) {
  const auto radii = [&](double length) { return format_number(length / g.radius) + " R"; };
  std::string why;
  if (std::isnan(g.phi_b)) {
    // Apart: "bulk_top, 6 R, reaches above ... 6 R" for 6.0000001 said nothing.
    why = "phi_b is undefined (NaN): bulk_top, " + format_apart(s.bulk_top, g.top / g.radius) +
          " R, reaches above the highest particle top, " +
          format_apart(g.top / g.radius, s.bulk_top) + " R";
  }
  if (std::isnan(g.phi_c)) {
    why += std::string(why.empty() ? "" : "; ") +
           "phi_c is undefined (NaN): its zone's top height_c, " + radii(g.height_c) +
           ", is not above perturbed_top, " + format_number(s.perturbed_top) + " R";
  }
  return why;
}

}  // namespace granpipe
