#include "compaction_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "ageing.hpp"
#include "compaction_laws.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/log.hpp"
#include "law_fit.hpp"
#include "power_spectrum.hpp"
#include "steady_state.hpp"

namespace granpipe::compaction {

namespace {

// The three global values, the law each follows and its unit.
struct Quantity {
  const char* name;
  std::vector<double> Series::*values;
  const Law& (*law)();
  const char* fit_name;
  const char* unit;
};
const std::array<Quantity, 3> kQuantities{{
    {"z_mean", &Series::z_mean, eq4_law, "eq4_z_mean", "R"},
    {"phi_b", &Series::phi_b, eq3_law, "eq3_phi_b", ""},
    {"phi_c", &Series::phi_c, eq3_law, "eq3_phi_c", ""},
}};

// The series' entries with fit_from <= tap <= fit_to.
Series within(const Series& s, double from, double to) {
  Series out;
  for (std::size_t k = 0; k < s.tap.size(); ++k) {
    if (s.tap[k] >= from && s.tap[k] <= to)
      out.add({s.tap[k], s.z_mean[k], s.phi_b[k], s.phi_c[k], 0.0, {}});
  }
  return out;
}

void add_law_fit(Results& results, const std::string& name, const Law& law, const LawFit& fit,
                 const std::string& doc) {
  results.add_scalar(name + "_status", static_cast<double>(fit.status), std::nan(""), "",
                     doc + ": " + describe(fit.status) + kCurveFitStatusCodes);
  results.add_scalar(name + "_scatter", fit.scatter, std::nan(""), "",
                     doc + ": rms residual of the points about the law (their sigma in the fit)");
  Fit out;
  out.model = law.formula;
  out.names = law.names;
  out.values = fit.value;  // NaN when not fitted: undefined, never 0
  out.errors = fit.error;
  out.covariance = fit.covariance;
  out.chi2 = fit.chi2;
  out.dof = fit.dof;
  results.add_fit(name, std::move(out));
}

// Each quantity beside its fitted law over the fit range, and the plots of both: the
// paper's Fig. 2 with Eqs. (3) and (4) drawn through it.
void add_fitted_curves(const Series& range, const std::array<LawFit, 3>& fits, Results& results) {
  Table t({"tap", "z_mean", "z_mean_eq4", "phi_b", "phi_b_eq3", "phi_c", "phi_c_eq3"},
          "each quantity and its fitted law (Eq. 4 for z_mean, Eq. 3 for phi_b and phi_c) over "
          "the fits' range; the law's column is NaN when it was not fitted");
  t.units = {"taps", "R", "R", "", "", "", ""};
  for (std::size_t k = 0; k < range.tap.size(); ++k) {
    std::vector<double> row{range.tap[k]};
    for (std::size_t q = 0; q < kQuantities.size(); ++q) {
      row.push_back((range.*kQuantities[q].values)[k]);
      row.push_back(law_value(kQuantities[q].law(), fits[q], range.tap[k]));
    }
    t.add_row(row);
  }
  results.add_table("fitted_laws", std::move(t));
  results.add_plot("eq3", {.table = "fitted_laws",
                           .x = "tap",
                           .y = {"phi_b", "phi_b_eq3", "phi_c", "phi_c_eq3"},
                           .xlabel = "tap",
                           .ylabel = "packing fraction",
                           .title = "compaction and the fits of Eq. (3)",
                           .logx = true});
  results.add_plot("eq4", {.table = "fitted_laws",
                           .x = "tap",
                           .y = {"z_mean", "z_mean_eq4"},
                           .xlabel = "tap",
                           .ylabel = "<Z>",
                           .title = "mean height and the fit of Eq. (4)",
                           .logx = true});
}

void report_fits(const Series& s, double from, double to, Results& results, Log& log) {
  results.add_scalar("fit_from", from, std::nan(""), "taps", "first tap of the fits' range");
  results.add_scalar("fit_to", to, std::nan(""), "taps", "last tap of the fits' range");
  if (from > to) {
    log.warn("compaction: fit_from: " + format_number(from) + " taps is past the fits' last tap, " +
             format_number(to) + ": no frame to fit; Eqs. (3) and (4) are left undefined");
  }
  const Series range = within(s, from, to);
  std::array<LawFit, 3> fits;
  for (std::size_t q = 0; q < kQuantities.size(); ++q) {
    const Law& law = kQuantities[q].law();
    fits[q] = fit_law(law, range.tap, range.*kQuantities[q].values);
    add_law_fit(results, kQuantities[q].fit_name, law, fits[q],
                std::string("fit of ") + kQuantities[q].name + " against the tap, taps " +
                    std::to_string(static_cast<long long>(from)) + " to " +
                    std::to_string(static_cast<long long>(to)));
    // Said, as stereology says its Eq. (7): only the _status scalar recorded it.
    if (fits[q].status != CurveFitStatus::Fitted && from <= to) {
      log.warn(std::string("compaction: ") + kQuantities[q].fit_name + ": " +
               describe(fits[q].status) + "; its parameters are left undefined");
    }
    const LeastDetermined least = least_determined(law, fits[q]);
    if (least.barely_determined()) {
      log.warn(std::string("compaction: ") + kQuantities[q].fit_name + ": fitted, but " +
               least.name + " = " + format_number(least.value) + " +- " +
               format_number(least.error) +
               ", an error above its value: the data barely "
               "determine the law");
    }
  }
  add_fitted_curves(range, fits, results);
}

void report_steady_state(const Series& ss, Results& results, Log& log) {
  for (const Quantity& q : kQuantities) {
    const SteadyState st = steady_state(ss.*q.values);
    const std::string name = q.name;
    // steady_frames counts every frame: say when a mean is of fewer.
    const auto all = static_cast<long>(ss.tap.size());
    if (st.frames > 0 && st.frames < all) {
      log.warn("compaction: " + name + " is undefined in " + std::to_string(all - st.frames) +
               " of the " + std::to_string(all) + " steady-state frames: " + name + "_ss and " +
               name + "_sigma are of the " + std::to_string(st.frames) + " with a value");
    }
    results.add_scalar(
        name + "_ss", st.mean, st.mean_error, q.unit,
        "steady-state mean of " + name + " (error as if the frames were independent)");
    results.add_scalar(name + "_sigma", st.sigma, std::nan(""), q.unit,
                       "sigma = sqrt(<(X - X_SS)^2>) of " + name + " in the steady state");
  }
  results.add_scalar("steady_frames", static_cast<double>(ss.tap.size()), std::nan(""), "",
                     "frames of the steady state");
}

// Fewer evenly spaced frames leave fewer than four frequencies for the slope.
constexpr std::size_t kMinSpectrumFrames = 8;

void report_spectrum(const Series& ss, Results& results, Log& log) {
  const EvenFrames even = evenly_spaced(ss.tap);
  results.add_scalar("spectrum_spacing", even.spacing, std::nan(""), "taps",
                     "spacing of the steady-state frames the spectrum uses");
  results.add_scalar("spectrum_frames", static_cast<double>(even.index.size()), std::nan(""), "",
                     "evenly spaced steady-state frames the spectrum uses");
  const bool enough = even.index.size() >= kMinSpectrumFrames;
  if (!enough) {
    log.warn("compaction: the power spectrum needs " + std::to_string(kMinSpectrumFrames) +
             " evenly spaced frames from steady_from on, got " + std::to_string(even.index.size()) +
             "; its slopes are left undefined");
  }
  Table t({"frequency", "z_mean", "phi_b", "phi_c"},
          "one-sided power spectrum of X - X_SS over the evenly spaced steady-state frames");
  t.units = {"1/taps", "R^2 taps", "taps", "taps"};
  std::array<Spectrum, 3> spectra;
  for (std::size_t q = 0; q < kQuantities.size(); ++q) {
    std::vector<double> values;
    for (std::size_t k : even.index) values.push_back((ss.*kQuantities[q].values)[k]);
    if (enough) spectra[q] = power_spectrum(values, even.spacing);
    const Slope slope = log_log_slope(spectra[q]);
    const auto undefined =
        std::count_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); });
    if (enough && undefined > 0) {
      log.warn(std::string("compaction: the power spectrum of ") + kQuantities[q].name +
               " and its slope are undefined (NaN): " + kQuantities[q].name + " is undefined in " +
               std::to_string(undefined) + " of the " + std::to_string(values.size()) +
               " evenly spaced frames");
    } else if (enough && std::isnan(slope.value)) {
      log.warn(std::string("compaction: the power spectrum of ") + kQuantities[q].name +
               " is zero at all but " + std::to_string(positive_powers(spectra[q])) +
               " frequencies (it hardly fluctuates); its slope is left undefined");
    }
    results.add_scalar(std::string("spectrum_slope_") + kQuantities[q].name, slope.value,
                       slope.error, "",
                       std::string("slope of ln S against ln f of ") + kQuantities[q].name +
                           " (f > 0; the paper finds about -1 to -1.5 for z_mean)");
  }
  for (std::size_t k = 0; k < spectra[0].frequency.size(); ++k)
    t.add_row(
        {spectra[0].frequency[k], spectra[0].power[k], spectra[1].power[k], spectra[2].power[k]});
  results.add_table("spectrum", std::move(t));
  results.add_plot("spectrum", {.table = "spectrum",
                                .x = "frequency",
                                .y = {"z_mean"},
                                .xlabel = "frequency (1/taps)",
                                .ylabel = "S of <Z> - <Z>_SS",
                                .title = "power spectrum of the fluctuations of <Z>",
                                .logx = true,
                                .logy = true});
}

void report_ageing(const Series& s, const std::vector<std::int64_t>& waiting_times,
                   Results& results, Log& log) {
  const Ageing a = ageing(s.tap, s.z_mean, waiting_times);
  for (const std::int64_t t_w : a.left_out)
    log.warn("compaction: waiting_times: " + std::to_string(t_w) + " is no frame's tap; left out");
  for (const std::int64_t t_w : waiting_times) {
    const auto at = [&](const AgeingPoint& p) { return p.t_w == static_cast<double>(t_w); };
    const bool left_out = std::find(a.left_out.begin(), a.left_out.end(), t_w) != a.left_out.end();
    if (!left_out && std::none_of(a.points.begin(), a.points.end(), at)) {
      log.warn("compaction: waiting_times: " + std::to_string(t_w) +
               " is the last frame's tap, with no frame after it; left out");
    }
  }
  Table points({"t_w", "t", "squared_difference"},
               "(<Z>(t_w) - <Z>(t_w + t))^2 of this realization: Eq. (5) before the mean over "
               "realizations (scripts/pool_ageing.py)");
  points.units = {"taps", "taps", "R^2"};
  Table fits({"t_w", "points", "status", "A_inf", "A_inf_err", "B", "B_err", "tau", "tau_err"},
             std::string("Eq. (6) fitted to this realization's squared differences, per t_w") +
                 kCurveFitStatusCodes);
  fits.units = {"taps", "", "", "R^2", "R^2", "", "", "taps", "taps"};
  std::string unfitted, undetermined;
  for (std::size_t k = 0; k < a.points.size();) {
    std::vector<double> t, y;
    const double t_w = a.points[k].t_w;
    for (; k < a.points.size() && a.points[k].t_w == t_w; ++k) {
      points.add_row({t_w, a.points[k].t, a.points[k].squared_difference});
      t.push_back(a.points[k].t);
      y.push_back(a.points[k].squared_difference);
    }
    const LawFit f = fit_law(eq6_law(), t, y);
    fits.add_row({t_w, static_cast<double>(t.size()), static_cast<double>(f.status), f.value[0],
                  f.error[0], f.value[1], f.error[1], f.value[2], f.error[2]});
    if (f.status != CurveFitStatus::Fitted)
      unfitted += (unfitted.empty() ? "" : ", ") + format_number(t_w);
    if (least_determined(eq6_law(), f).barely_determined())
      undetermined += (undetermined.empty() ? "" : ", ") + format_number(t_w);
  }
  if (!unfitted.empty()) {
    log.warn("compaction: Eq. (6) not fitted at t_w = " + unfitted +
             " (ageing_fits' status); its parameters there are left undefined");
  }
  if (!undetermined.empty()) {
    log.warn("compaction: Eq. (6) fitted at t_w = " + undetermined +
             " with an error above a parameter's value: the data barely determine it there");
  }
  results.add_table("ageing", std::move(points));
  results.add_table("ageing_fits", std::move(fits));
}

}  // namespace

void Series::add(const FramePoint& p) {
  tap.push_back(p.tap);
  z_mean.push_back(p.z_mean);
  phi_b.push_back(p.phi_b);
  phi_c.push_back(p.phi_c);
}

// A range asked past the run's last tap ends there: the tap reported as its end is one
// the fits saw. (The last tap is known only at the end, when refusing would lose the run.)
double range_end(double asked, double last, const char* name, Log& log) {
  if (asked < 0.0) return last;
  if (asked <= last) return asked;
  log.warn(std::string("compaction: ") + name + ": " + format_number(asked) +
           " taps is past the last frame's tap, " + format_number(last) + "; it ends there");
  return last;
}

void report_compaction(const Series& series, const ReportSettings& settings, Results& results,
                       Log& log) {
  const double last = series.tap.back();
  report_fits(series, settings.fit_from, range_end(settings.fit_to, last, "fit_to", log), results,
              log);
  const double steady_from = settings.steady_from < 0.0 ? 0.5 * last : settings.steady_from;
  if (steady_from > last) {
    log.warn("compaction: steady_from: " + format_number(steady_from) +
             " taps is past the last frame's tap, " + format_number(last) +
             "; the steady state and its spectrum are undefined (NaN)");
  }
  results.add_scalar("steady_from", steady_from, std::nan(""), "taps",
                     "first tap of the steady state");
  const Series ss = within(series, steady_from, last);
  report_steady_state(ss, results, log);
  report_spectrum(ss, results, log);
  report_ageing(series, settings.waiting_times, results, log);
}

}  // namespace granpipe::compaction
