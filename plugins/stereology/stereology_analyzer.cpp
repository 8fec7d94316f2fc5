#include "stereology_analyzer.hpp"

#include <cmath>
#include <string>

#include "granpipe/format_number.hpp"
#include "granpipe/stereology.hpp"

namespace granpipe::stereology {

Schema schema() {
  Schema s;
  // The bins are counted per frame: a step of 3.6e-6 passed the first frame (9.8e6 bins,
  // 2.3 GB) and was refused at a taller one, hours into a run. At 1e-3 R the cap of 1e7
  // bins is a packing 1e4 R tall.
  s.real("step", 0.1, "width of the bins of the vertical and transversal profiles, at least 0.001")
      .min(1e-3)
      .unit("mean radii");
  declare_stereology_settings(s);
  // A band's fraction is the difference of two caps' volumes over the band's: at 1e-9 R
  // rounding made it negative.
  s.real("lateral_band", 7.0,
         "the lateral fraction is that within this distance of either side across x, the "
         "central fraction that of the rest (undefined where narrower than 0.001 R); at least "
         "0.001")
      .min(kNarrowestZone)
      .unit("mean radii");
  s.real("fit_from", 5.0, "Eq. (7) is fitted to the vertical profile from this height up")
      .min(0.0)
      .unit("mean radii");
  return s;
}

namespace {

std::vector<std::string> per_frame_columns() {
  std::vector<std::string> c{"frame",         "step",         "tap",         "phi_b",
                             "phi_c",         "height_c",     "phi_lateral", "phi_central",
                             "delta_lateral", "delta_central"};
  for (const char* name : kFermiNames) {
    c.push_back(std::string("fit_") + name);
    c.push_back(std::string("fit_") + name + "_err");
  }
  return c;
}

Table profile_table(const MeanProfile& mean, const std::vector<double>& first,
                    const std::vector<double>& last, double step, const std::string& doc) {
  Table t({"position", "phi", "phi_err", "phi_first", "phi_last"}, doc);
  t.units = {"mean radii", "", "", "", ""};
  const auto at = [](const std::vector<double>& p, std::size_t k) {
    return k < p.size() ? p[k] : 0.0;
  };
  for (std::size_t k = 0; k < mean.bins().size(); ++k) {
    t.add_row({(static_cast<double>(k) + 0.5) * step, mean.bins()[k].mean(),
               mean.bins()[k].standard_error(), at(first, k), at(last, k)});
  }
  return t;
}

}  // namespace

StereologyAnalyzer::StereologyAnalyzer(const PluginContext& ctx)
    : log_(ctx.log),
      per_frame_(ctx.stream_table(
          "per_frame",
          Table(per_frame_columns(),
                "per-frame phi_b, phi_c (its zone's top height_c in mean radii), lateral and "
                "central fractions and their increases over the first frame, Eq. (7) fit"))) {
  const Params& p = ctx.params;
  settings_.step = p.real("step");
  if (!ctx.params_path.empty()) settings_.params = ctx.params_path;
  settings_.global = stereology_settings(p, ctx.param("perturbed_factor"));
  settings_.lateral_band = p.real("lateral_band");
  settings_.fit_from = p.real("fit_from");
}

void StereologyAnalyzer::consume(const Frame& frame, FrameCache& /*cache*/) {
  const ProfileMeasurement m = measure_profiles(frame, settings_);
  if (!first_) first_ = m;
  if (!m.fit.fitted() && frames_ == 0) {
    log_.warn("stereology: Eq. (7) not fitted to the first frame's profile (" +
              describe(m.fit.status) + "); its columns are NaN where that happens");
  }
  warn_undefined(frame, m);
  transversal_step_ = m.transversal_step;
  if (std::isfinite(m.global.phi_b)) phi_b_.add(m.global.phi_b);
  if (std::isfinite(m.global.phi_c)) phi_c_.add(m.global.phi_c);
  lateral_.add(m.lateral);
  if (std::isfinite(m.central)) central_.add(m.central);
  by_leg_.add(frame, {m.global.phi_b, m.global.phi_c});
  vertical_.add(m.vertical);
  transversal_.add(m.transversal);
  last_ = m.global;
  last_vertical_ = m.vertical;
  last_transversal_ = m.transversal;

  const auto tap = frame.integer_observable("tap");
  std::vector<double> row{static_cast<double>(frames_),
                          static_cast<double>(frame.step),
                          tap ? static_cast<double>(*tap) : std::nan(""),
                          m.global.phi_b,
                          m.global.phi_c,
                          m.global.height_c / m.global.radius,
                          m.lateral,
                          m.central,
                          m.lateral - first_->lateral,
                          m.central - first_->central};
  for (int q = 0; q < kFermiParameters; ++q) {
    row.push_back(m.fit.value[q]);
    row.push_back(m.fit.error[q]);
  }
  per_frame_.add_row(row);
  ++frames_;
}

// NaN is never a silent answer: the first frame where a fraction is undefined says why.
void StereologyAnalyzer::warn_undefined(const Frame& frame, const ProfileMeasurement& m) {
  if (!undefined_.pending()) return;
  std::string why = undefined_fractions(m.global, settings_.global);
  if (std::isnan(m.central)) {
    why += std::string(why.empty() ? "" : "; ") +
           "phi_central is undefined (NaN): the box leaves less than " +
           format_number(kNarrowestZone) + " R beside two bands of lateral_band, " +
           format_number(settings_.lateral_band) + " R";
  }
  if (why.empty()) return;
  undefined_.warn(log_, "stereology: frame " + std::to_string(frames_) + " (step " +
                            std::to_string(frame.step) + "): " + why);
}

void StereologyAnalyzer::add_profiles(Results& results) const {
  results.add_table("vertical_profile",
                    profile_table(vertical_, first_->vertical, last_vertical_, settings_.step,
                                  "packing fraction of horizontal slices against height above "
                                  "the bottom: mean over frames, first and last frame"));
  results.add_table(
      "transversal_profile",
      profile_table(transversal_, first_->transversal, last_transversal_, transversal_step_,
                    "packing fraction of vertical slices across x (from the low "
                    "side), heights 0..height_c: mean, first and last frame"));
  results.add_plot("vertical_profile", {.table = "vertical_profile",
                                        .x = "position",
                                        .y = {"phi", "phi_first", "phi_last"},
                                        .xlabel = "height / R",
                                        .ylabel = "packing fraction",
                                        .title = "vertical profile"});
  results.add_plot("transversal_profile", {.table = "transversal_profile",
                                           .x = "position",
                                           .y = {"phi_first", "phi_last"},
                                           .xlabel = "x / R",
                                           .ylabel = "packing fraction",
                                           .title = "transversal profile"});
}

void StereologyAnalyzer::add_mean_fit(Results& results) const {
  std::vector<double> z, phi;
  for (std::size_t k = 0; k < vertical_.bins().size(); ++k) {
    z.push_back((static_cast<double>(k) + 0.5) * settings_.step);
    phi.push_back(vertical_.bins()[k].mean());
  }
  const CurveFit fit = fit_fermi_profile(z, phi, settings_.fit_from);
  if (!fit.fitted()) {
    log_.warn("stereology: Eq. (7) not fitted to the mean profile (" + describe(fit.status) + ")");
  }
  results.add_fit("eq7_mean_profile",
                  result_fit(fit, kFermiFormula, {std::begin(kFermiNames), std::end(kFermiNames)}));
}

void StereologyAnalyzer::finish(Results& results) {
  results.add_scalar("frames", static_cast<double>(frames_));
  results.add_table("per_frame", per_frame_.table());
  if (frames_ == 0) return;
  results.add_mean("phi_b", phi_b_, "", "packing fraction between the bottom and bulk_top");
  results.add_mean("phi_c", phi_c_, "",
                   "packing fraction of the zone below height_c, its bottom layer corrected");
  results.add_scalar("phi_b_last", last_.phi_b, std::nan(""), "", "phi_b of the last frame");
  results.add_scalar("phi_c_last", last_.phi_c, std::nan(""), "", "phi_c of the last frame");
  results.add_mean("phi_lateral", lateral_, "",
                   "packing fraction within lateral_band of x's sides");
  results.add_mean("phi_central", central_, "", "packing fraction of the rest across x");
  add_profiles(results);
  add_mean_fit(results);
  if (!by_leg_.empty()) {
    results.add_table("by_leg", by_leg_.table("phi_b and phi_c per leg of a ramp (0 first "
                                              "increase, 1 decreasing, 2 increasing) and "
                                              "epsilon, over the frames saved there"));
  }
}

}  // namespace granpipe::stereology
