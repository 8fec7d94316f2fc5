#include "packing_analyzer.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "granpipe/bin_count.hpp"
#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/coordinate_spacing.hpp"
#include "granpipe/cut_profile.hpp"
#include "granpipe/format_number.hpp"
#include "lowest_surface.hpp"

namespace granpipe::packing {

Schema schema() {
  Schema s;
  declare_contact_tolerance(s);
  s.choice<Top>("top", Top::Auto,
                "top of the region before exclude_top: the highest particle top (surface), the "
                "lowest point of the free surface, over columns at least one mean diameter wide "
                "(lowest_surface: for heaped beds), the container's top (container), or surface "
                "for an open-top container and container otherwise (auto)");
  s.real("exclude_bottom", 0.0,
         "the region starts this far above the base (the bottom layers ordered by the wall)")
      .min(0.0)
      .unit("mean diameters");
  s.real("exclude_top", 0.0, "the region ends this far below its top (the loose free surface)")
      .min(0.0)
      .unit("mean diameters");
  s.real("exclude_sides", 0.0, "the region keeps this far from each lateral side")
      .min(0.0)
      .unit("mean diameters");
  s.real("profile_step", 0.05,
         "spacing of the horizontal cuts of the vertical profile phi(y), from the base up; 0: "
         "no profile")
      .min(0.0)
      .unit("mean diameters");
  s.real("cuts_step", 0.01,
         "spacing of the horizontal cuts through the region averaged into phi_cuts (midpoint "
         "rule: bias O(step^1.5) in 2D, O(step^2) in 3D for layers aligned with the cuts); 0: "
         "no phi_cuts")
      .min(0.0)
      .unit("mean diameters");
  return s;
}

namespace {

const char* axis_name(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }

std::string frame_name(const Frame& f) { return "frame at step " + std::to_string(f.step); }

double mean_diameter(const Frame& f) { return f.size() ? 2.0 * f.radius().mean() : 0.0; }

struct Heights {
  double base = 0.0;  // the container's bottom
  double top = 0.0;   // the top of the region before exclude_top
};

// `columns`: the horizontal extent of the region, for the lowest surface; `top_name`: where
// `top` sits in the pipeline.
Heights vertical_range(const Frame& f, Top top, const Region& columns,
                       const std::string& top_name) {
  const Container& c = f.container;
  const int v = f.dim - 1;
  if (top == Top::Auto) top = c.boundary[v][1] == Boundary::Open ? Top::Surface : Top::Container;
  if (top != Top::Container && c.periodic(v)) {
    throw InputError(top_name + ": expected \"container\" or \"auto\" for a container " +
                     "periodic along " + axis_name(v) + " (" + frame_name(f) + "), got \"" +
                     choice_name(top) + "\"");
  }
  Heights h{c.wall_at(v, 0), c.wall_at(v, 1)};
  if (top == Top::Surface) {
    h.top = f.size() ? (f.position().col(v) + f.radius()).maxCoeff() : h.base;
  } else if (top == Top::LowestSurface) {
    h.top = lowest_surface(f, columns, mean_diameter(f), h.base);
  }
  return h;
}

double mean_over(const IntArray& z, const std::vector<char>& in, long count) {
  if (count == 0) return std::nan("");
  double sum = 0.0;
  for (Eigen::Index k = 0; k < z.size(); ++k) sum += in[static_cast<std::size_t>(k)] ? z[k] : 0;
  return sum / static_cast<double>(count);
}

// Centres on the region's faces (a lattice's, with exclude_* of half a diameter) count on
// its lower faces only, whatever their rounding: the region's bounded sides are moved down
// by 1e-9 diameters, or by 64 units in the last place of the largest coordinate when that is
// more, to count them. Before, number_density and z_mean of one lattice jumped with its
// radius (x (2R)^3: 1, 1.728 or 0.512). A region spanning a whole period stays: the centres
// are wrapped into it, and moved it would lose those wrapped just below its top.
constexpr double kFaceRounding = 64.0;  // spacings of doubles a face is moved by at least

Region moved_down(const Frame& frame, Region r, double diameter) {
  const double shift =
      std::max(1e-9 * diameter, kFaceRounding * double_spacing(largest_coordinate(frame)));
  for (int a = 0; a < frame.dim; ++a) {
    const Container& c = frame.container;
    if (c.periodic(a) && r.hi[a] - r.lo[a] >= c.length(a)) continue;
    r.lo[a] -= shift;
    r.hi[a] -= shift;
  }
  return r;
}

}  // namespace

Region packing_region(const Frame& frame, const PackingSettings& s) {
  const Container& c = frame.container;
  if (c.shape != ContainerShape::Box) {
    throw InputError("packing: " + frame_name(frame) +
                     ": expected a box container (the measuring region is a box), got a " +
                     to_string(c.shape));
  }
  const int dim = frame.dim, v = dim - 1;
  const double d = mean_diameter(frame);
  Region r;
  r.dim = dim;
  for (int a = 0; a < v; ++a) {
    r.lo[a] = c.wall_at(a, 0) + s.exclude_sides * d;
    r.hi[a] = c.wall_at(a, 1) - s.exclude_sides * d;
  }
  const Heights h = vertical_range(frame, s.top, r, s.params + ".top");
  r.lo[v] = h.base + s.exclude_bottom * d;
  r.hi[v] = h.top - s.exclude_top * d;
  for (int a = 0; a < dim; ++a) {
    if (!(r.hi[a] > r.lo[a])) {
      std::ostringstream m;
      m << "packing: " << frame_name(frame)
        << ": expected a measuring region of positive size, got " << axis_name(a) << " from "
        << r.lo[a] << " to " << r.hi[a] << " (exclude_bottom " << s.exclude_bottom
        << ", exclude_top " << s.exclude_top << ", exclude_sides " << s.exclude_sides
        << " mean diameters of " << d << ")";
      throw InputError(m.str());
    }
  }
  return r;
}

PackingMeasurement measure_packing(const Frame& frame, FrameCache& cache,
                                   const PackingSettings& s) {
  if (frame.size() == 0) {
    throw InputError("packing: " + frame_name(frame) + ": expected particles, got none");
  }
  PackingMeasurement m;
  m.diameter = mean_diameter(frame);
  // Moved by more, the region's faces miscount centres (4 of 16 at 1e14 from the origin).
  require_fine_positions(largest_coordinate(frame), kFaceRounding, m.diameter, "mean diameter",
                         "packing: " + frame_name(frame));
  m.region = packing_region(frame, s);
  const Region& region = m.region;
  const double volume = region.volume();
  m.phi = particle_measure_in(frame, region) / volume;

  const std::vector<char> in = centres_in(frame, moved_down(frame, region, m.diameter));
  m.centres = std::count(in.begin(), in.end(), char{1});
  m.number_density = static_cast<double>(m.centres) / volume;

  const DistanceContacts& contacts = contacts_by_distance(frame, cache, s.tolerance);
  m.z_mean = mean_over(contacts.coordination(frame.size(), false), in, m.centres);
  m.z_mean_with_walls = mean_over(contacts.coordination(frame.size(), true), in, m.centres);

  // (A relative 1e-9 keeps rounding from adding a cut just above a top.)
  if (s.profile_step > 0.0) {
    const double step = s.profile_step * m.diameter;
    // The profile covers the whole bed, also when the region stops at the lowest surface.
    const Heights h = vertical_range(frame, s.top == Top::LowestSurface ? Top::Surface : s.top,
                                     region, s.params + ".top");
    check_bin_count((h.top - h.base) / m.diameter, s.profile_step, s.params + ".profile_step",
                    "cuts of the profile");
    // A step past the bed's height left a single cut above it (phi 0 at half the step).
    check_step_fits((h.top - h.base) / m.diameter, s.profile_step, s.params + ".profile_step",
                    "the bed's height in diameters");
    const int count = static_cast<int>(std::ceil((h.top - h.base) / step - 1e-9));
    m.profile = cut_fractions(frame, region, frame.dim - 1, h.base, step, count);
  }
  m.phi_cuts = std::nan("");
  if (s.cuts_step > 0.0) {
    // The midpoint rule over the region's own height, so that it estimates exactly the
    // quantity phi measures.
    const int v = frame.dim - 1;
    const double height = region.hi[v] - region.lo[v];
    check_bin_count(height / m.diameter, s.cuts_step, s.params + ".cuts_step", "cuts of phi_cuts");
    const int cuts =
        std::max(1, static_cast<int>(std::ceil(height / (s.cuts_step * m.diameter) - 1e-9)));
    const std::vector<double> f =
        cut_fractions(frame, region, v, region.lo[v], height / cuts, cuts);
    m.phi_cuts = std::accumulate(f.begin(), f.end(), 0.0) / cuts;
  }
  return m;
}

PackingAnalyzer::PackingAnalyzer(const PluginContext& ctx)
    : log_(ctx.log),
      per_frame_(ctx.stream_table(
          "per_frame", Table({"frame", "step", "time", "phi", "number_density", "z_mean"},
                             "per-frame packing fraction, number density and coordination"))) {
  const Params& p = ctx.params;
  settings_.tolerance = p.real(kContactToleranceName);
  settings_.exclude_bottom = p.real("exclude_bottom");
  settings_.exclude_top = p.real("exclude_top");
  settings_.exclude_sides = p.real("exclude_sides");
  settings_.profile_step = p.real("profile_step");
  settings_.cuts_step = p.real("cuts_step");
  settings_.top = p.choice<Top>("top");
  if (!ctx.params_path.empty()) settings_.params = ctx.params_path;
}

void PackingAnalyzer::consume(const Frame& frame, FrameCache& cache) {
  coordination_.resize(0);
  if (frame.size() == 0) {
    if (skipped_++ == 0) log_.warn("packing: " + frame_name(frame) + " has no particles; skipped");
    return;
  }
  dim_ = frame.dim;
  if (coarse_.pending()) {
    const std::string why = coarse_for_contacts(frame, settings_.tolerance);
    if (!why.empty()) coarse_.warn(log_, "packing: " + frame_name(frame) + ": " + why);
  }
  const PackingMeasurement m = measure_packing(frame, cache, settings_);
  const DistanceContacts& contacts = contacts_by_distance(frame, cache, settings_.tolerance);
  coordination_ = contacts.coordination(frame.size(), false);
  // A Monte Carlo packing leaves gaps: its z_mean of 0 is true at the tolerance, yet averaged
  // with a deposition's about 6 it read as a coordination number.
  if (frame.size() > 1 && contacts.pairs == 0 && untouching_.pending()) {
    untouching_.warn(log_, "packing: " + frame_name(frame) + ": no two particles touch within " +
                               kContactToleranceName + " " + format_number(settings_.tolerance) +
                               ": its z_mean is 0 (packings of Monte Carlo moves leave gaps; "
                               "a larger contact_tolerance counts near contacts)");
  }
  phi_.add(m.phi);
  density_.add(m.number_density);
  if (m.centres > 0) {
    z_.add(m.z_mean);
    z_walls_.add(m.z_mean_with_walls);
  } else {
    centreless_.warn(log_, "packing: " + frame_name(frame) +
                               ": no particle centred in the region: its z_mean is undefined "
                               "(NaN in per_frame, left out of the mean)");
  }
  by_ramp_.add(frame, {m.phi, m.z_mean});
  per_frame_.add_row({static_cast<double>(frames_), static_cast<double>(frame.step), frame.time,
                      m.phi, m.number_density, m.centres > 0 ? m.z_mean : std::nan("")});
  if (settings_.cuts_step > 0.0) phi_cuts_.add(m.phi_cuts);
  if (settings_.profile_step > 0.0) {
    profile_.add(m.profile);
  }
  ++frames_;
}

void PackingAnalyzer::finish(Results& results) {
  const std::string per_volume = dim_ == 2 ? "1/length^2" : "1/length^3";
  results.add_mean("phi", phi_, "",
                   "packing fraction of the region, exact (cut particles counted in part)");
  results.add_mean("number_density", density_, per_volume,
                   "particle centres in the region per unit volume");
  results.add_mean("z_mean", z_, "",
                   "mean number of particle contacts of the particles centred in the region");
  results.add_mean("z_mean_with_walls", z_walls_, "", "z_mean with particle-wall contacts counted");
  if (!by_ramp_.empty()) {
    results.add_table("by_ramp", by_ramp_.table("phi and z_mean per ramp branch (0 first increase, "
                                                "1 decreasing, 2 increasing) and the tap amplitude "
                                                "A, pooled over cycles"));
    results.add_plot("by_ramp", {.table = "by_ramp",
                                 .x = "amplitude",
                                 .y = {"phi"},
                                 .xlabel = "tap amplitude A",
                                 .ylabel = "packing fraction",
                                 .title = "packing fraction on the ramp branches"});
  }
  if (settings_.cuts_step > 0.0) {
    results.add_mean(
        "phi_cuts", phi_cuts_, "",
        "mean area fraction of horizontal cuts through the region (stereological estimate of phi)");
  }
  results.add_table("per_frame", per_frame_.table());
  results.add_scalar("frames", static_cast<double>(frames_), std::nan(""), "",
                     "frames measured (frames without particles are skipped)");
  if (settings_.profile_step > 0.0) {
    Table t({"height", "phi", "phi_err"},
            "area fraction of horizontal cuts against height above the base, mean over frames");
    t.units = {"mean diameters", "", ""};
    for (std::size_t k = 0; k < profile_.bins().size(); ++k) {
      t.add_row({(static_cast<double>(k) + 0.5) * settings_.profile_step, profile_.bins()[k].mean(),
                 profile_.bins()[k].standard_error()});
    }
    results.add_table("profile", std::move(t));
    results.add_plot("profile", {.table = "profile",
                                 .x = "height",
                                 .y = {"phi"},
                                 .xlabel = "height above the base / mean diameter",
                                 .ylabel = "area fraction of horizontal cuts",
                                 .title = "vertical packing-fraction profile"});
  }
}

}  // namespace granpipe::packing
