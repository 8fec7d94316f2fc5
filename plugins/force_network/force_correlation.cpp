#include "force_correlation.hpp"

#include <cmath>

#include "granpipe/cell_list.hpp"

namespace granpipe::force_network {

ForceCorrelation force_correlation(const Coordinates& points, const std::vector<double>& f,
                                   const Container& container, int dim, double r_max, int bins,
                                   const std::string& where) {
  const auto n = static_cast<std::size_t>(bins);
  ForceCorrelation out{r_max, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  if (points.rows() < 2) return out;
  const CellList cells(points, container, dim, r_max,
                       where + ": F(r) up to r_max (parameter r_max)");
  const double width = r_max / bins;
  // Each unordered pair once: the ratio of Eq. (12), whose double sum counts each twice,
  // is the same.
  cells.for_each_pair([&](int i, int j, const double*, double r2) {
    const auto k = static_cast<std::size_t>(std::sqrt(r2) / width);
    if (k >= n) return;  // r == r_max exactly
    out.product_sum[k] += f[static_cast<std::size_t>(i)] * f[static_cast<std::size_t>(j)];
    out.pairs[k] += 1.0;
  });
  return out;
}

}  // namespace granpipe::force_network
