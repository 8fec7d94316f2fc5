#include "pores_analyzer.hpp"

#include <cmath>

namespace granpipe::pores {

Schema schema() {
  Schema s;
  s.real("tolerance", 1e-9,
         "two Delaunay cells whose circumspheres agree within tolerance * R (centre and radius) "
         "are one pore; a cell thinner than tolerance * R is flat and no pore")
      .range(1e-14, 1e-3)
      .unit("particle radii");
  s.choice<RegionKind>("region", RegionKind::All,
                       "pores counted: all, or those whose centre lies in the box container "
                       "shrunk by margin (inner)");
  s.real("margin", 2.0,
         "region inner: distance kept from every wall and below the top (the container's, or "
         "the highest particle top for an open top)")
      .min(0.0)
      .unit("particle radii");
  s.real("height", 0.0, "region inner: height of the region above its bottom; 0: up to the top")
      .min(0.0)
      .unit("particle radii");
  s.real("bin_width", 0.01, "bin width of P(xi)").range(1e-6, 1.0);
  s.real("xi_max", 1.0, "upper end of the histogram of xi = r/R").range(1e-3, 1e3);
  return s;
}

namespace {

PoreSettings settings_from(const Params& p) {
  PoreSettings s;
  s.tolerance = p.real("tolerance");
  s.region.kind = p.choice<RegionKind>("region");
  s.region.margin = p.real("margin");
  s.region.height = p.real("height");
  return s;
}

}  // namespace

PoresAnalyzer::PoresAnalyzer(const PluginContext& ctx)
    : settings_(settings_from(ctx.params)),
      statistics_(ctx.params.real("bin_width"), ctx.params.real("xi_max")),
      per_frame_(ctx.stream_table(
          "per_frame", Table({"frame", "step", "time", "pores", "spheres", "pores_per_sphere", "nu",
                              "flat_cells"},
                             "per-frame pores and particle centres in the region, nu = <xi^3> "
                             "and the cells left out as flat"))) {}

void PoresAnalyzer::consume(const Frame& frame, FrameCache&) {
  const PoreMeasurement m =
      measure_pores(frame, settings_, "pores: frame at step " + std::to_string(frame.step));
  statistics_.add(m);
  double xi3 = 0.0;
  for (double xi : m.xi) xi3 += xi * xi * xi;
  const auto pores = static_cast<double>(m.xi.size());
  const double nan = std::nan("");
  per_frame_.add_row({static_cast<double>(frames_), static_cast<double>(frame.step), frame.time,
                      pores, static_cast<double>(m.spheres),
                      m.spheres > 0 ? pores / static_cast<double>(m.spheres) : nan,
                      m.xi.empty() ? nan : xi3 / pores, static_cast<double>(m.flat_cells)});
  ++frames_;
}

void PoresAnalyzer::finish(Results& results) {
  results.add_scalar("frames", static_cast<double>(frames_), std::nan(""), "", "frames measured");
  statistics_.report(results);
  results.add_table("per_frame", per_frame_.table());
}

}  // namespace granpipe::pores
