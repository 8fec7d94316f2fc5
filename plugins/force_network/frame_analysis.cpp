#include "frame_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/bin_count.hpp"

namespace granpipe::force_network {

FrameAnalysis analyse_frame(const Frame& frame, const Settings& settings,
                            const std::string& where) {
  FrameAnalysis a;
  a.forces = force_contacts(frame, settings.force, where);
  a.networks = find_networks(frame, a.forces.edges);
  a.strong = strong_network(frame, a.forces, a.networks);
  a.scaled = scaled_forces(a.forces, a.forces.samples, a.forces.mean);
  if (settings.f_max <= 0.0 && !a.scaled.empty()) {
    // The PDF reaches the frame's largest f: with more bins than a PDF has, it stopped short
    // of it and left the larger forces out of the PDF and its fit without a word.
    check_bin_count(*std::max_element(a.scaled.begin(), a.scaled.end()), settings.bin_width,
                    where + ": bin_width (f_max 0: the PDF reaches the frame's largest f)", "bins",
                    kMaxPdfBins);
  }
  a.pdf = force_pdf(a.scaled, pdf_edges(a.scaled, settings.f_max, settings.bin_width));
  a.fit = fit_pdf(a.pdf, eq11_request(settings.min_fit_samples));
  return a;
}

PaperFrame paper_frame(const Frame& frame, const FrameAnalysis& a, long index,
                       const Settings& settings, const std::string& where) {
  PaperFrame p{index, frame.time, a.forces.loaded, a.pdf, a.fit, {}, {}};
  p.correlation =
      force_correlation(contact_points(frame, a.forces.samples, where), a.scaled, frame.container,
                        frame.dim, settings.r_max, settings.r_bins, where);
  if (!settings.by_pass.empty()) {
    p.passes = pass_subsets(frame, a.forces, a.pdf.edges, a.fit, settings, where);
  }
  return p;
}

std::vector<std::string> per_frame_columns() {
  return {"frame",
          "time",
          "networks",
          "largest_particles",
          "largest_contacts",
          "other_networks",
          "other_contacts",
          "z_largest",
          "z_mean",
          "network_contacts",
          "samples",
          "mean_force",
          "strong_contacts",
          "strong_particles",
          "strong_particles_in_largest",
          "strong_largest_particles",
          "strong_largest_contacts",
          "loaded_pair_contacts",
          "eq11_status",
          "a",
          "a_err",
          "b",
          "b_err",
          "beta",
          "beta_err",
          "chi2_per_dof"};
}

std::vector<double> per_frame_row(long index, double time, Eigen::Index particles,
                                  const FrameAnalysis& a) {
  const auto d = [](auto x) { return static_cast<double>(x); };
  const ComponentSize largest = a.networks.largest();
  const double z_largest =
      largest.particles > 0 ? 2.0 * d(largest.edges) / d(largest.particles) : std::nan("");
  const double z_mean = particles > 0 ? 2.0 * d(a.forces.edges.size()) / d(particles) : 0.0;
  const PdfFit& fit = a.fit;
  return {d(index),
          time,
          d(a.networks.size.size()),
          d(largest.particles),
          d(largest.edges),
          d(a.networks.others()),
          d(a.networks.edges_of_others()),
          z_largest,
          z_mean,
          d(a.forces.edges.size()),
          d(a.forces.samples.size()),
          a.forces.mean,
          d(a.strong.contacts),
          d(a.strong.particles),
          d(a.strong.particles_in_largest),
          d(a.strong.largest.particles),
          d(a.strong.largest.edges),
          d(a.forces.loaded),
          d(static_cast<int>(fit.status)),
          fit.value[kA],
          fit.error[kA],
          fit.value[kB],
          fit.error[kB],
          fit.value[kBeta],
          fit.error[kBeta],
          fit.dof > 0 && fit.fitted() ? fit.chi2 / fit.dof : std::nan("")};
}

}  // namespace granpipe::force_network
