#pragma once
// The pore distributions pooled over frames as counts and sums, so that runs merge: the
// size distribution P(xi), the volume distribution xi^3 P(xi), nu = <xi^3>, pores per
// sphere and the shares of Bernal's canonical holes.
#include <cstddef>
#include <vector>

#include "granpipe/results.hpp"
#include "measure_pores.hpp"

namespace granpipe::pores {

class PoreStatistics {
 public:
  // Bins of `bin_width` from xi = 0 to the first edge at or above xi_max.
  PoreStatistics(double bin_width, double xi_max);
  void add(const PoreMeasurement& m);
  void report(Results& results) const;

  long pores() const { return pores_; }
  double nu() const;  // <xi^3> over every pore, NaN for none
  const std::vector<double>& counts() const { return counts_; }
  // P(xi), its error and xi^3 P(xi) at the bin centres.
  Table distribution_table() const;
  // Per canonical hole (bernal_holes() order, then the pores near none).
  const std::vector<long>& hole_counts() const { return hole_counts_; }
  const std::vector<double>& hole_volumes() const { return hole_volumes_; }

 private:
  Table bernal_table() const;

  double bin_width_;
  std::vector<double> counts_;  // pores per bin
  long pores_ = 0, spheres_ = 0, outside_ = 0, flat_cells_ = 0, untangent_cells_ = 0,
       fifth_sphere_cells_ = 0, apollonius_vertices_ = 0;
  double xi3_sum_ = 0.0;
  std::vector<long> hole_counts_;
  std::vector<double> hole_volumes_;  // sums of xi^3
};

}  // namespace granpipe::pores
