#include "span_histogram.hpp"

#include <cmath>
#include <string>

#include "granpipe/bin_count.hpp"
#include "granpipe/errors.hpp"

namespace granpipe::arches {

void SpanHistogram::add(double span) {
  // Frames are checked for finite positions before analysis; a bad span is a bug.
  if (!(span >= 0.0) || !std::isfinite(span)) {
    throw InternalError("span histogram: expected a finite span >= 0, got " + std::to_string(span));
  }
  // The histogram grows to the widest span: refused before a bin width far too small for it
  // asks for more memory than there is (checked only when it grows: most spans fall in it).
  const double bin = std::floor(span / width_);
  if (bin >= static_cast<double>(counts_.size())) {
    check_bin_count(span, width_, width_name_, "bins of the span distributions");
    counts_.resize(static_cast<std::size_t>(bin) + 1, 0);
  }
  ++counts_[static_cast<std::size_t>(bin)];
  ++total_;
}

Histogram SpanHistogram::density(const std::string& xlabel, const std::string& doc) const {
  Histogram h;
  h.density = true;
  h.xlabel = xlabel;
  h.doc = doc;
  const std::size_t bins = counts_.empty() ? 1 : counts_.size();
  // No spans: a density of nothing is undefined (NaN), never 0.
  const double norm = total_ > 0 ? 1.0 / (static_cast<double>(total_) * width_) : std::nan("");
  for (std::size_t b = 0; b <= bins; ++b) h.edges.push_back(static_cast<double>(b) * width_);
  for (std::size_t b = 0; b < bins; ++b) {
    const double c = b < counts_.size() ? static_cast<double>(counts_[b]) : 0.0;
    h.values.push_back(c * norm);
    h.errors.push_back(std::sqrt(c) * norm);
  }
  return h;
}

}  // namespace granpipe::arches
