#pragma once
// P0(sigma) pooled over frames as counts, so that runs merge: probes whose nearest sphere
// surface is farther than sigma R, on a grid of sigma, and the particle and region volumes
// whose ratio is the packing fraction of the Percus-Yevick column.
#include <vector>

#include "granpipe/results.hpp"

namespace granpipe::pores {

class VoidProbability {
 public:
  // sigma = 0, step, 2 step, ... below sigma_max, then sigma_max.
  VoidProbability(double sigma_step, double sigma_max);
  double sigma_max() const { return sigma_.back(); }
  // gaps: of one frame's probes, in units of R.
  void add(const std::vector<double>& gaps, double particle_volume, double region_volume);
  double phi() const;  // NaN before any frame
  Table table() const;
  void report(Results& results) const;

 private:
  std::vector<double> sigma_;
  std::vector<long> free_;  // probes farther than sigma from every sphere
  long probes_ = 0;
  double particle_volume_ = 0.0, region_volume_ = 0.0;
};

}  // namespace granpipe::pores
