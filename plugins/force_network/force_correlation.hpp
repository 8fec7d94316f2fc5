#pragma once
// The spatial force–force correlation of Eq. (12) of the paper,
//   F(r) = sum_i sum_{j != i} delta(r_ij - r) f_i f_j / sum_i sum_{j != i} delta(r_ij - r),
// over contact points, r_ij the distance between contact points i and j (minimum image
// along periodic sides) and f the normal forces scaled by the mean: in each bin of r, the
// mean of f_i f_j over the pairs of contacts at that distance. Pairs are found with a
// cell list (cells of side r_max), never by looping over all M^2 pairs.
#include <cmath>
#include <string>
#include <vector>

#include "granpipe/container.hpp"
#include "granpipe/property_table.hpp"

namespace granpipe::force_network {

struct ForceCorrelation {
  double r_max = 0.0;
  std::vector<double> product_sum;  // per bin: sum of f_i f_j over the pairs
  std::vector<double> pairs;        // per bin: unordered pairs of contacts

  std::size_t bins() const { return pairs.size(); }
  double lower(std::size_t k) const {
    return r_max * static_cast<double>(k) / static_cast<double>(bins());
  }
  double upper(std::size_t k) const { return lower(k + 1); }
  // F(r) of bin k; undefined (NaN) when no pair falls in it: 0 would read as forces
  // anticorrelated there.
  double value(std::size_t k) const {
    return pairs[k] > 0 ? product_sum[k] / pairs[k] : std::nan("");
  }
};

// `points` holds one contact point per row (dim columns), `f` its scaled force. Throws
// InputError after `where` when a periodic side is shorter than 2 r_max.
ForceCorrelation force_correlation(const Coordinates& points, const std::vector<double>& f,
                                   const Container& container, int dim, double r_max, int bins,
                                   const std::string& where);

}  // namespace granpipe::force_network
