#pragma once
// The paper's volume distribution of pores in v = xi^3 (Sec. IV.B, Fig. 10b):
// rho_v(v) = xi/3 P(xi), the density in v weighted by the pores' volume, so that
// integral rho_v dv = nu = <xi^3>; and the fit of its tail to rho_v ~ A exp(-v / lambda),
// which the paper finds compatible with lambda = nu (a Poisson law of free volume).
// Pooled over frames as counts and sums, so that runs merge.
#include <vector>

#include "granpipe/curve_fit.hpp"
#include "granpipe/results.hpp"

namespace granpipe::pores {

class VolumeDistribution {
 public:
  // Bins of `bin_width` from v = 0 to the first edge at or above v_max; the tail fitted
  // from v_tail up.
  VolumeDistribution(double bin_width, double v_max, double v_tail);
  void add(const std::vector<double>& xi);
  // rho_v per bin: the bin's sum of v over (all pores counted x bin width).
  std::vector<double> density() const;
  // The fit of A exp(-v / lambda) (parameters A, lambda) to the non-empty bins from v_tail
  // up, each weighted by its Poisson error.
  CurveFit tail_fit(double nu) const;
  // The table, the tail fit and its status scalar; returns the fit's status.
  CurveFitStatus report(Results& results, double nu) const;

 private:
  double centre(std::size_t k) const { return (static_cast<double>(k) + 0.5) * bin_width_; }

  double bin_width_, v_tail_;
  std::vector<double> counts_, volumes_;  // per bin: pores, sum of v
  long pores_ = 0;                        // all pores added, in range or not
};

}  // namespace granpipe::pores
