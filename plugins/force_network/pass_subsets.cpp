#include "pass_subsets.hpp"

#include "granpipe/errors.hpp"

namespace granpipe::force_network {

namespace {

// The force-network contacts captured by pass 1 .. k, in ascending row order.
std::vector<Eigen::Index> captured_by(const ForceContacts& forces, const IndexArray& pass, long k) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index row : forces.edges) {
    if (pass[row] >= 1 && pass[row] <= k) rows.push_back(row);
  }
  return rows;
}

long largest_pass(const IndexArray& pass, const Settings& settings, const std::string& where) {
  const long largest = pass.size() > 0 ? static_cast<long>(pass.maxCoeff()) : 0;
  if (largest > kMaxPasses) {
    throw InputError(where + ": contact column " + settings.by_pass +
                     " (by_pass): expected pass "
                     "numbers up to " +
                     std::to_string(kMaxPasses) + ", got " + std::to_string(largest));
  }
  return largest;
}

PdfFit free_fit(const ForcePdf& pdf, const PdfFit& full, long min_samples) {
  FitRequest r = eq11_request(min_samples);
  if (full.fitted()) r.start = full.value;
  r.start[kAlpha] = r.start[kGamma] = 0.0;
  r.free = {true, true, true, true, false};
  return fit_pdf(pdf, r);
}

PdfFit shift_fit(const ForcePdf& pdf, const PdfFit& full, long min_samples) {
  if (!full.fitted()) {
    PdfFit none;
    none.status = FitStatus::NoReference;
    return none;
  }
  FitRequest r;
  r.start = full.value;
  r.start[kAlpha] = r.start[kGamma] = 0.0;
  r.free = {false, false, true, false, true};
  r.min_samples = min_samples;
  return fit_pdf(pdf, r);
}

}  // namespace

const IndexArray& pass_column(const Frame& frame, const Settings& settings,
                              const std::string& where) {
  if (!frame.contacts || !frame.contacts->has(settings.by_pass)) {
    throw InputError(where + ": expected the contact column " + settings.by_pass +
                     " (parameter by_pass), got contacts without it");
  }
  const IndexArray& pass = frame.contacts->get<IndexArray>(settings.by_pass);
  // (A negative number counted as no pass, without a word.)
  Eigen::Index row = 0;
  if (pass.size() > 0 && pass.minCoeff(&row) < 0) {
    throw InputError(where + ": contact " + std::to_string(row) + ": contact column " +
                     settings.by_pass + " (by_pass): expected a pass number, 0 (none) or more, " +
                     "got " + std::to_string(pass[row]));
  }
  return pass;
}

std::vector<PassSubset> pass_subsets(const Frame& frame, const ForceContacts& forces,
                                     const std::vector<double>& pdf_edges, const PdfFit& full,
                                     const Settings& settings, const std::string& where) {
  const IndexArray& pass = pass_column(frame, settings, where);
  std::vector<PassSubset> out;
  for (long k = 1, last = largest_pass(pass, settings, where); k <= last; ++k) {
    const std::vector<Eigen::Index> rows = captured_by(forces, pass, k);
    const std::vector<double> f = scaled_forces(forces, rows, forces.mean);
    PassSubset s;
    s.pass = k;
    s.contacts = static_cast<long>(rows.size());
    s.pdf = force_pdf(f, pdf_edges);
    s.correlation = force_correlation(contact_points(frame, rows, where), f, frame.container,
                                      frame.dim, settings.r_max, settings.r_bins, where);
    s.free_fit = free_fit(s.pdf, full, settings.min_fit_samples);
    s.shift_fit = shift_fit(s.pdf, full, settings.min_fit_samples);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace granpipe::force_network
