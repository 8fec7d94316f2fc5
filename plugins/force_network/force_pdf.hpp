#pragma once
// The probability density of scaled forces f = F_n / <F_n>: a histogram normalised by the
// number of samples and the bin width, so that it integrates to 1 when the bins hold
// every sample, with Poisson errors sqrt(count) / (samples x width).
#include <vector>

namespace granpipe::force_network {

struct ForcePdf {
  std::vector<double> edges;   // bins + 1, ascending
  std::vector<double> counts;  // per bin
  long samples = 0;            // every sample, those beyond the last edge included

  std::size_t bins() const { return counts.size(); }
  double width(std::size_t k) const { return edges[k + 1] - edges[k]; }
  double centre(std::size_t k) const { return 0.5 * (edges[k] + edges[k + 1]); }
  // NaN (undefined, not zero) when there are no samples.
  double density(std::size_t k) const;
  double error(std::size_t k) const;
};

// The most bins a PDF has: its fit runs over every bin, and a frame whose largest force is
// an outlier (f = 13 732 at bin width 0.2: 68 660 bins) took 13 s a fit; the PDFs of the
// papers span f up to about 10.
inline constexpr double kMaxPdfBins = 10000;

// Bins of width `width` from 0 to f_max; f_max <= 0: to the smallest multiple of `width`
// holding the largest of `f` (so that the histogram holds every sample; one bin when `f`
// is empty or all zero), but at most kMaxPdfBins bins (the analyzer refuses a frame that
// would need more: analyse_frame).
std::vector<double> pdf_edges(const std::vector<double>& f, double f_max, double width);

ForcePdf force_pdf(const std::vector<double>& f, const std::vector<double>& edges);

}  // namespace granpipe::force_network
