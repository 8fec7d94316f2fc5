#include "frame_report.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace granpipe::force_network {

namespace {

const char* const kEq13 = "P(f) = a (1 - b exp(-(f - alpha)^2)) exp(-beta (f - gamma))";

// Adds the fit (when it has values) and its status scalar.
void add_fit(Results& results, const std::string& name, const PdfFit& fit, const std::string& doc) {
  results.add_scalar(name + "_status", static_cast<double>(fit.status), std::nan(""), "",
                     doc + ": " + describe(fit.status) +
                         " (0 fitted, 1 too few samples, 2 no "
                         "convergence, 3 no reference fit, 4 a parameter not determined)");
  if (!fit.fitted()) return;
  Fit out;
  out.model = kEq13;
  out.covariance = fit.covariance;
  out.chi2 = fit.chi2;
  out.dof = fit.dof;
  for (int q : fit.fitted_parameters) {
    out.names.push_back(kParameterNames[static_cast<std::size_t>(q)]);
    out.values.push_back(fit.value[static_cast<std::size_t>(q)]);
    out.errors.push_back(fit.error[static_cast<std::size_t>(q)]);
  }
  results.add_fit(name, std::move(out));
}

void add_pdf_table(const PaperFrame& p, Results& results) {
  Table t({"f_lo", "f_hi", "f", "density", "error", "count", "eq11"},
          "PDF of f = |F_n|/<F_n> over the force-network contacts of the paper's frame, with "
          "the Eq. (11) fit at the bin centre (NaN when not fitted)");
  for (std::size_t k = 0; k < p.pdf.bins(); ++k) {
    const double model = p.fit.fitted() ? eq13(p.fit.value, p.pdf.centre(k)) : std::nan("");
    t.add_row({p.pdf.edges[k], p.pdf.edges[k + 1], p.pdf.centre(k), p.pdf.density(k),
               p.pdf.error(k), p.pdf.counts[k], model});
  }
  results.add_table("pdf", std::move(t));
  results.add_plot("pdf", {.table = "pdf",
                           .x = "f",
                           .y = {"density", "eq11"},
                           .xlabel = "f",
                           .ylabel = "P(f)",
                           .title = "force PDF and Eq. (11)",
                           .logy = true});
}

void add_correlation_table(const PaperFrame& p, Results& results) {
  Table t({"r_lo", "r_hi", "r", "F", "pairs"},
          "force-force correlation F(r) of Eq. (12) over the contact points of the paper's "
          "frame (F undefined, NaN, where no pair falls)");
  t.units = {"length", "length", "length", "", ""};
  const ForceCorrelation& c = p.correlation;
  for (std::size_t k = 0; k < c.bins(); ++k) {
    t.add_row({c.lower(k), c.upper(k), 0.5 * (c.lower(k) + c.upper(k)), c.value(k), c.pairs[k]});
  }
  results.add_table("correlation", std::move(t));
  results.add_plot("correlation", {.table = "correlation",
                                   .x = "r",
                                   .y = {"F"},
                                   .xlabel = "r",
                                   .ylabel = "F(r)",
                                   .title = "force-force correlation"});
}

// Per pass k: the subset's contacts and its two Eq. (13) fits, in one table and as fits.
void add_pass_fits(const PaperFrame& p, Results& results) {
  Table t({"pass", "contacts", "free_status", "free_a", "free_a_err", "free_b", "free_b_err",
           "free_alpha", "free_alpha_err", "free_beta", "free_beta_err", "free_chi2_per_dof",
           "shift_status", "shift_alpha", "shift_alpha_err", "shift_gamma", "shift_gamma_err",
           "shift_chi2_per_dof"},
          "Eq. (13) fits of the PDF of the contacts of passes 1..k: free (a, b, alpha, beta; "
          "gamma = 0) and shift (a, b, beta of the full network's Eq. (11) fit; alpha, gamma "
          "free); status 0 fitted, 1 too few samples, 2 no convergence, 3 no reference fit, 4 "
          "a parameter not determined; values NaN when not fitted");
  const auto per_dof = [](const PdfFit& f) { return f.fitted() ? f.chi2 / f.dof : std::nan(""); };
  for (const PassSubset& s : p.passes) {
    const Parameters &fv = s.free_fit.value, &fe = s.free_fit.error;
    const Parameters &sv = s.shift_fit.value, &se = s.shift_fit.error;
    t.add_row({static_cast<double>(s.pass), static_cast<double>(s.contacts),
               static_cast<double>(s.free_fit.status), fv[kA], fe[kA], fv[kB], fe[kB], fv[kAlpha],
               fe[kAlpha], fv[kBeta], fe[kBeta], per_dof(s.free_fit),
               static_cast<double>(s.shift_fit.status), sv[kAlpha], se[kAlpha], sv[kGamma],
               se[kGamma], per_dof(s.shift_fit)});
    const std::string name = "pass_" + std::to_string(s.pass) + "_eq13";
    add_fit(results, name + "_free", s.free_fit,
            "Eq. (13) fit, gamma = 0, of passes 1.." + std::to_string(s.pass));
    add_fit(results, name + "_shift", s.shift_fit,
            "Eq. (13) fit, a, b, beta of eq11, of passes 1.." + std::to_string(s.pass));
  }
  results.add_table("pass_fits", std::move(t));
}

// The PDFs of the subsets beside the full network's, on the same bins.
void add_pass_pdfs(const PaperFrame& p, Results& results) {
  std::vector<std::string> columns{"f", "density_all", "error_all"};
  for (const PassSubset& s : p.passes) {
    columns.push_back("density_pass_" + std::to_string(s.pass));
    columns.push_back("error_pass_" + std::to_string(s.pass));
  }
  Table t(std::move(columns),
          "PDF of f = |F_n|/<F_n> (the full network's mean) of the contacts of passes 1..k, "
          "beside the full network's, on its bins");
  for (std::size_t k = 0; k < p.pdf.bins(); ++k) {
    std::vector<double> row{p.pdf.centre(k), p.pdf.density(k), p.pdf.error(k)};
    for (const PassSubset& s : p.passes) {
      row.push_back(s.pdf.density(k));
      row.push_back(s.pdf.error(k));
    }
    t.add_row(row);
  }
  results.add_table("pass_pdf", std::move(t));
  Plot plot{.table = "pass_pdf",
            .x = "f",
            .y = {"density_all"},
            .xlabel = "f",
            .ylabel = "P(f)",
            .title = "force PDF by MST pass",
            .logy = true};
  for (const PassSubset& s : p.passes) plot.y.push_back("density_pass_" + std::to_string(s.pass));
  results.add_plot("pass_pdf", plot);
}

// F(r) of the subsets beside the full network's.
void add_pass_correlations(const PaperFrame& p, Results& results) {
  std::vector<std::string> columns{"r", "F_all"};
  for (const PassSubset& s : p.passes) {
    columns.push_back("F_pass_" + std::to_string(s.pass));
    columns.push_back("pairs_pass_" + std::to_string(s.pass));
  }
  Table t(std::move(columns),
          "F(r) of Eq. (12) of the contacts of passes 1..k (forces scaled by "
          "the full network's mean), beside the full network's");
  t.units[0] = "length";
  const ForceCorrelation& c = p.correlation;
  for (std::size_t k = 0; k < c.bins(); ++k) {
    std::vector<double> row{0.5 * (c.lower(k) + c.upper(k)), c.value(k)};
    for (const PassSubset& s : p.passes) {
      row.push_back(s.correlation.value(k));
      row.push_back(s.correlation.pairs[k]);
    }
    t.add_row(row);
  }
  results.add_table("pass_correlation", std::move(t));
  Plot plot{.table = "pass_correlation",
            .x = "r",
            .y = {"F_all"},
            .xlabel = "r",
            .ylabel = "F(r)",
            .title = "force-force correlation by MST pass"};
  for (const PassSubset& s : p.passes) plot.y.push_back("F_pass_" + std::to_string(s.pass));
  results.add_plot("pass_correlation", plot);
}

}  // namespace

void report_paper_frame(const PaperFrame& p, Results& results) {
  if (p.index < 0) return;
  results.add_scalar("paper_frame", static_cast<double>(p.index), std::nan(""), "",
                     "frame (0-based, in pipeline order) with the most particle-particle contacts "
                     "with |F_n| > 0, the earliest of equals: the frame of the full tables");
  results.add_scalar("paper_time", p.time, std::nan(""), "time", "time of that frame");
  results.add_scalar("paper_loaded_contacts", static_cast<double>(p.loaded), std::nan(""), "",
                     "its particle-particle contacts with |F_n| > 0");
  add_fit(results, "eq11", p.fit, "Eq. (11) fit of the PDF (alpha = gamma = 0)");
  add_pdf_table(p, results);
  add_correlation_table(p, results);
  if (p.passes.empty()) return;
  add_pass_fits(p, results);
  add_pass_pdfs(p, results);
  add_pass_correlations(p, results);
}

}  // namespace granpipe::force_network
