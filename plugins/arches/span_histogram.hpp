#pragma once
// Histogram of arch spans pooled over frames, with bins of fixed width from 0 that grow
// as wider spans appear (memory grows with the widest span, not with run length).
#include <string>
#include <utility>
#include <vector>

#include "granpipe/results.hpp"

namespace granpipe::arches {

class SpanHistogram {
 public:
  // `width_name`: where the bin width sits in the pipeline, for the refusal of too many bins.
  SpanHistogram(double bin_width, std::string width_name)
      : width_(bin_width), width_name_(std::move(width_name)) {}
  void add(double span);
  long total() const { return total_; }
  // Probability density n(x): counts / (total * bin width), with the Poisson error of
  // each count. With no spans at all: one bin [0, width) of density NaN (undefined).
  Histogram density(const std::string& xlabel, const std::string& doc) const;

 private:
  double width_;
  std::string width_name_;
  std::vector<long> counts_;
  long total_ = 0;
};

}  // namespace granpipe::arches
