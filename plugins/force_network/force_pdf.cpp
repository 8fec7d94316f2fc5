#include "force_pdf.hpp"

#include <algorithm>
#include <cmath>

namespace granpipe::force_network {

double ForcePdf::density(std::size_t k) const {
  return samples > 0 ? counts[k] / (static_cast<double>(samples) * width(k)) : std::nan("");
}

double ForcePdf::error(std::size_t k) const {
  return samples > 0 ? std::sqrt(counts[k]) / (static_cast<double>(samples) * width(k))
                     : std::nan("");
}

std::vector<double> pdf_edges(const std::vector<double>& f, double f_max, double width) {
  if (f_max <= 0.0) {
    const double largest = f.empty() ? 0.0 : *std::max_element(f.begin(), f.end());
    double bins = std::ceil(largest / width);
    if (bins * width < largest) bins += 1.0;  // the quotient rounded down to a whole number
    f_max = std::clamp(bins, 1.0, kMaxPdfBins) * width;
  }
  // f_max rounded up to whole bins: bins of f_max / round(f_max / width) were not the
  // bin_width asked for (0.1667 for 0.2).
  const auto bins = static_cast<std::size_t>(std::max(1.0, std::ceil(f_max / width - 1e-9)));
  std::vector<double> edges(bins + 1);
  for (std::size_t k = 0; k <= bins; ++k) edges[k] = width * static_cast<double>(k);
  return edges;
}

ForcePdf force_pdf(const std::vector<double>& f, const std::vector<double>& edges) {
  ForcePdf pdf{edges, std::vector<double>(edges.size() - 1, 0.0), static_cast<long>(f.size())};
  for (double x : f) {
    // The last bin is closed, so that the largest sample (the top edge) is counted.
    auto it = std::upper_bound(edges.begin(), edges.end(), x);
    if (x == edges.back()) --it;
    if (it == edges.begin() || it == edges.end()) continue;  // below 0 or beyond f_max
    pdf.counts[static_cast<std::size_t>(it - edges.begin() - 1)] += 1.0;
  }
  return pdf;
}

}  // namespace granpipe::force_network
