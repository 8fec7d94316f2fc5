#include "pores_analyzer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "granpipe/bin_count.hpp"
#include "granpipe/coordinate_spacing.hpp"
#include "granpipe/curve_fit.hpp"
#include "granpipe/deepest_overlap.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/random.hpp"
#include "granpipe/region.hpp"
#include "pore_region.hpp"
#include "void_probes.hpp"

namespace granpipe::pores {

Schema schema() {
  const auto inner_region = [](const Params& p) {
    return p.choice<RegionKind>("region") == RegionKind::Inner;
  };
  const auto probing = [](const Params& p) { return p.integer("probes") > 0; };
  Schema s;
  s.real("tolerance", 1e-9,
         "two Delaunay cells whose circumspheres agree within tolerance * R (centre and radius; "
         "widened by what rounding leaves of a thin cell's sphere) are one pore; a cell thinner "
         "than tolerance * R is flat and no pore")
      .range(1e-14, 1e-3)
      .unit("particle radii");
  declare_max_overlap(s, 0.05,
                      "soft-sphere data press a few percent; a frame with a deeper one is refused");
  s.choice<RegionKind>("region", RegionKind::All,
                       "pores counted: all whose centre lies in the container, or those in it "
                       "shrunk by margin (inner)");
  s.real("margin", 2.0,
         "region inner: distance kept from every wall and below the top (the container's, or "
         "the highest particle top for an open top)")
      .min(0.0)
      .unit("particle radii")
      .only_where("region inner", inner_region);
  s.real("height", 0.0, "region inner: height of the region above its bottom; 0: up to the top")
      .min(0.0)
      .unit("particle radii")
      .only_where("region inner", inner_region);
  s.real("bin_width", 0.01, "bin width of P(xi)").range(1e-6, 1.0);
  s.real("xi_max", 1.0, "upper end of the histogram of xi = r/R").range(1e-3, 1e3);
  s.real("v_bin_width", 0.005, "bin width of the volume distribution rho_v(v), v = xi^3")
      .range(1e-6, 1.0);
  s.real("v_max", 0.5, "upper end of the volume distribution").range(1e-3, 1e3);
  s.real("v_tail", 0.0711,
         "rho_v's exponential tail is fitted from this v up (default: the octahedral site's "
         "(sqrt 2 - 1)^3, where the paper's distributions part)")
      .min(0.0);
  s.boolean("frame_distributions", false,
            "also P(xi), xi^3 P(xi) and rho_v(v) of every frame, in the tables frame_xi and "
            "frame_v (the paper's Fig. 10: one packing at several stages of its compaction)");
  s.integer("probes", 0,
            "random probes of P0(sigma) per frame, uniform in the region cut to the box "
            "container; 0: P0 not measured")
      .range(0.0, 1e8);
  s.real("sigma_step", 0.05, "step of the grid of P0(sigma)")
      .range(1e-4, 1.0)
      .only_where("probes > 0", probing);
  s.real("sigma_max", 1.0, "largest probe radius of P0(sigma)")
      .range(0.0, 10.0)
      .unit("particle radii")
      .only_where("probes > 0", probing);
  s.boolean("pore_table", false,
            "also a table of every pore of every frame: centre, xi, Delaunay cells merged, "
            "whether in the region (a row per pore: some 6 per sphere)");
  return s;
}

namespace {

const Property kCellVolume{"voronoi_volume",
                           Scope::Particle,
                           ValueType::Real,
                           1,
                           "length^3",
                           "volume of the particle's Voronoi cell (Laguerre cell, weights r^2, for "
                           "unequal radii); NaN where undefined (unbounded, or beyond an open "
                           "surface or a cylinder)"};
const Property kLocalFraction{"local_packing_fraction",
                              Scope::Particle,
                              ValueType::Real,
                              1,
                              "",
                              "particle volume over its voronoi_volume; NaN where undefined"};

PoreSettings settings_from(const PluginContext& ctx) {
  const Params& p = ctx.params;
  PoreSettings s;
  s.threads = ctx.threads;
  s.tolerance = p.real("tolerance");
  s.max_overlap = p.real("max_overlap");
  s.max_overlap_param = ctx.param("max_overlap");
  s.region.kind = p.choice<RegionKind>("region");
  s.region.margin = p.real("margin");
  s.region.height = p.real("height");
  return s;
}

// The bin width parameter `width`, refused when its histogram up to `top` would have more
// bins than memory holds (checked before the histogram is made).
double checked_bin_width(const PluginContext& ctx, const std::string& width,
                         const std::string& top) {
  const double w = ctx.params.real(width);
  check_bin_count(ctx.params.real(top), w, ctx.param(width), "bins up to " + top);
  check_step_fits(ctx.params.real(top), w, ctx.param(width), top);
  return w;
}

// The probes look sigma_max R beyond each point for the nearest surface: along a periodic
// side shorter than twice that (with the largest radius) one sphere would be met through two
// images. Refused naming the parameter, not in the neighbour search's terms.
void check_probe_reach(const Frame& frame, double reach, const std::string& param,
                       const std::string& where) {
  const double range = reach + frame.radius().maxCoeff();
  for (int a = 0; a < 3; ++a) {
    if (!frame.container.periodic(a) || frame.container.length(a) >= 2.0 * range) continue;
    throw InputError(where + ": P0 probes look up to " + format_number(range) +
                     " from each point (" + param +
                     " times the mean radius, and the largest radius): expected periodic sides "
                     "of at least twice that, got " +
                     format_number(frame.container.length(a)) + " along " + "xyz"[a] + "; lower " +
                     param + " or set probes 0 (and it to its default)");
  }
}

}  // namespace

PoresAnalyzer::PoresAnalyzer(const PluginContext& ctx)
    : settings_(settings_from(ctx)),
      log_(ctx.log),
      statistics_(checked_bin_width(ctx, "bin_width", "xi_max"), ctx.params.real("xi_max")),
      volumes_(checked_bin_width(ctx, "v_bin_width", "v_max"), ctx.params.real("v_max"),
               ctx.params.real("v_tail")),
      seeds_(ctx.seeds),
      probes_(static_cast<long>(ctx.params.integer("probes"))),
      void_probability_(ctx.params.real("sigma_step"), ctx.params.real("sigma_max")),
      sigma_max_param_(ctx.param("sigma_max")),
      per_frame_(ctx.stream_table(
          "per_frame", Table({"frame", "step", "time", "pores", "spheres", "pores_per_sphere", "nu",
                              "flat_cells"},
                             "per-frame pores and particle centres in the region, nu = <xi^3> "
                             "and the cells left out as flat"))),
      bin_width_(ctx.params.real("bin_width")),
      xi_max_(ctx.params.real("xi_max")),
      v_bin_width_(ctx.params.real("v_bin_width")),
      v_max_(ctx.params.real("v_max")) {
  if (ctx.params.boolean("pore_table")) {
    pore_table_ = ctx.stream_table(
        "pore_table", Table({"frame", "step", "x", "y", "z", "xi", "cells", "in_region"},
                            "every pore of each frame (each once along periodic sides): its "
                            "centre, xi, the Delaunay cells merged into it, 1 if counted in "
                            "the region"));
  }
  if (!ctx.params.boolean("frame_distributions")) return;
  frame_xi_ =
      ctx.stream_table("frame_xi", Table({"frame", "step", "xi", "P", "xi3_P"},
                                         "P(xi) and xi^3 P(xi) of each frame, at the bin centres"));
  frame_v_ = ctx.stream_table(
      "frame_v", Table({"frame", "step", "v", "rho_v"}, "rho_v(v) of each frame, v = xi^3"));
}

void PoresAnalyzer::add_frame_distributions(const Frame& frame, const PoreMeasurement& m) {
  const auto frame_index = static_cast<double>(frames_), step = static_cast<double>(frame.step);
  PoreStatistics one(bin_width_, xi_max_);
  one.add(m);
  const Table xi = one.distribution_table();
  for (std::size_t k = 0; k < xi.rows(); ++k) {
    frame_xi_->add_row(
        {frame_index, step, xi.column("xi")[k], xi.column("P")[k], xi.column("xi3_P")[k]});
  }
  VolumeDistribution volumes(v_bin_width_, v_max_, 0.0);
  volumes.add(m.xi);
  const std::vector<double> rho = volumes.density();
  for (std::size_t k = 0; k < rho.size(); ++k) {
    frame_v_->add_row({frame_index, step, (static_cast<double>(k) + 0.5) * v_bin_width_, rho[k]});
  }
}

void PoresAnalyzer::add_pore_rows(const Frame& frame, const PoreMeasurement& m) {
  const auto frame_index = static_cast<double>(frames_), step = static_cast<double>(frame.step);
  for (std::size_t k = 0; k < m.pores.size(); ++k) {
    const Pore& p = m.pores[k];
    pore_table_->add_row({frame_index, step, p.centre[0], p.centre[1], p.centre[2],
                          p.radius / m.radius - 1.0, static_cast<double>(p.cells),
                          static_cast<double>(m.in_region[k])});
  }
}

void PoresAnalyzer::keep_cells(const Frame& frame, const PoreMeasurement& m) {
  cell_volume_ = m.cell_volume;
  // A hidden sphere's empty cell has no packing fraction: NaN, as undefined volumes give.
  local_fraction_ = (4.0 * M_PI / 3.0) * frame.radius().cube() / cell_volume_;
  local_fraction_ = (cell_volume_ > 0.0).select(local_fraction_, std::nan(""));
  undefined_volumes_ += m.undefined_volumes;
  hidden_spheres_ += m.hidden_spheres;
}

std::vector<Property> PoresAnalyzer::publishes() const { return {kCellVolume, kLocalFraction}; }

void PoresAnalyzer::publish(PropertyTable& columns) {
  columns.get<Eigen::ArrayXd>(kCellVolume.name) = cell_volume_;
  columns.get<Eigen::ArrayXd>(kLocalFraction.name) = local_fraction_;
}

// Each frame its own stream, so that P0 does not depend on which frames a run skips.
void PoresAnalyzer::probe_voids(const Frame& frame, double mean_radius, const std::string& where) {
  const Region box =
      probe_region(frame, pore_region(frame, settings_.region, mean_radius, where), where);
  const double reach = void_probability_.sigma_max() * mean_radius;
  check_probe_reach(frame, reach, sigma_max_param_, where);
  RandomStream stream = seeds_.stream("probes", static_cast<std::uint64_t>(frames_));
  std::vector<double> gaps = probe_gaps(frame, box, probes_, reach, stream, where);
  for (double& gap : gaps) gap /= mean_radius;
  void_probability_.add(gaps, particle_measure_in(frame, box), box.volume());
}

// Cells whose circumspheres agree within tolerance x R are one pore, so the positions must
// be finer than that: far from the origin their rounding splits a lattice's pores (an SC
// lattice of radius 0.05 at 10^6: 170 pores for 125). Said once; a random packing has no
// such cells, so it is no refusal.
void PoresAnalyzer::warn_if_coarse(const Frame& frame, const std::string& where) {
  if (warned_coarse_ || frame.size() == 0) return;
  const double farthest = largest_coordinate(frame);
  const double rounding = double_spacing(farthest);
  const double length = settings_.tolerance * frame.radius().mean();
  if (!(4.0 * rounding > length)) return;
  warned_coarse_ = true;
  // The schema allows tolerances up to 1e-3: past it only the origin can move.
  const double needed = 8.0 * rounding / frame.radius().mean();
  log_.warn(where + ": positions up to " + format_number(farthest) +
            " from the origin are rounded to " + format_number(rounding) +
            ", more than a quarter of tolerance x the mean radius (" + format_number(length) +
            "): pores of one site may be counted apart; " +
            (needed <= 1e-3 ? "raise tolerance to " + format_number(needed) + " or " : "") +
            "move the origin into the packing");
}

void PoresAnalyzer::consume(const Frame& frame, FrameCache&) {
  const std::string where = "pores: frame at step " + std::to_string(frame.step);
  warn_if_coarse(frame, where);
  const PoreMeasurement m = measure_pores(frame, settings_, where);
  statistics_.add(m);
  volumes_.add(m.xi);
  if (frame_xi_) add_frame_distributions(frame, m);
  if (pore_table_) add_pore_rows(frame, m);
  keep_cells(frame, m);
  if (probes_ > 0) probe_voids(frame, m.radius, where);
  double xi3 = 0.0;
  for (double xi : m.xi) xi3 += xi * xi * xi;
  const auto pores = static_cast<double>(m.xi.size());
  const double nan = std::nan("");
  per_frame_.add_row({static_cast<double>(frames_), static_cast<double>(frame.step), frame.time,
                      pores, static_cast<double>(m.spheres),
                      m.spheres > 0 ? pores / static_cast<double>(m.spheres) : nan,
                      m.xi.empty() ? nan : xi3 / pores, static_cast<double>(m.flat_cells)});
  frames_without_spheres_ += m.spheres == 0 ? 1 : 0;
  ++frames_;
}

void PoresAnalyzer::finish(Results& results) {
  results.add_scalar("frames", static_cast<double>(frames_), std::nan(""), "", "frames measured");
  if (frames_ > 0 && statistics_.pores() == 0) {
    // Every distribution is NaN then: said, never left for a reader to take as zeros.
    log_.warn(
        "pores: no pore in the region of any frame: P(xi), nu, rho_v and the shares of "
        "Bernal's holes are undefined (NaN); a larger region (margin, height) holds some");
  }
  if (frames_without_spheres_ > 0) {
    log_.warn("pores: " + std::to_string(frames_without_spheres_) + " of " +
              std::to_string(frames_) +
              " frame(s) have no particle centre in the region: their pores_per_sphere is "
              "undefined (NaN)" +
              (frames_without_spheres_ == frames_ ? ", and so is the pooled one" : ""));
  }
  statistics_.report(results);
  if (const CurveFitStatus tail = volumes_.report(results, statistics_.nu());
      tail != CurveFitStatus::Fitted && statistics_.pores() > 0) {
    log_.warn("pores: the fit of rho_v's tail (v >= v_tail), " + describe(tail) +
              ": A and lambda are undefined (NaN)");
  }
  if (probes_ > 0) void_probability_.report(results);
  results.add_scalar("undefined_volumes", static_cast<double>(undefined_volumes_), std::nan(""), "",
                     "spheres whose Voronoi (Laguerre) cell is undefined (voronoi_volume NaN): "
                     "unbounded, or reaching beyond an open surface or a cylinder, all frames");
  results.add_scalar("hidden_spheres", static_cast<double>(hidden_spheres_), std::nan(""), "",
                     "unequal radii: spheres whose Laguerre cell is empty (voronoi_volume 0, "
                     "local_packing_fraction NaN), all frames");
  results.add_table("per_frame", per_frame_.table());
  if (pore_table_) results.add_table("pore_table", pore_table_->table());
  if (frame_xi_) {
    results.add_table("frame_xi", frame_xi_->table());
    results.add_table("frame_v", frame_v_->table());
  }
}

}  // namespace granpipe::pores
