#include "pore_statistics.hpp"

#include <cmath>
#include <limits>

#include "bernal_holes.hpp"

namespace granpipe::pores {

PoreStatistics::PoreStatistics(double bin_width, double xi_max)
    : bin_width_(bin_width),
      counts_(static_cast<std::size_t>(std::ceil(xi_max / bin_width - 1e-9)), 0.0),
      hole_counts_(bernal_holes().size() + 1, 0),
      hole_volumes_(bernal_holes().size() + 1, 0.0) {}

void PoreStatistics::add(const PoreMeasurement& m) {
  pores_ += static_cast<long>(m.xi.size());
  spheres_ += m.spheres;
  flat_cells_ += m.flat_cells;
  untangent_cells_ += m.untangent_cells;
  fifth_sphere_cells_ += m.fifth_sphere_cells;
  apollonius_vertices_ += m.apollonius_vertices;
  for (double xi : m.xi) {
    const double volume = xi * xi * xi;
    xi3_sum_ += volume;
    const std::size_t hole = nearest_hole(xi);
    ++hole_counts_[hole];
    hole_volumes_[hole] += volume;
    const double bin = std::floor(xi / bin_width_);
    if (bin >= 0.0 && bin < static_cast<double>(counts_.size())) {
      counts_[static_cast<std::size_t>(bin)] += 1.0;
    } else {
      ++outside_;
    }
  }
}

double PoreStatistics::nu() const {
  return pores_ > 0 ? xi3_sum_ / static_cast<double>(pores_)
                    : std::numeric_limits<double>::quiet_NaN();
}

Table PoreStatistics::distribution_table() const {
  Table t({"xi", "count", "P", "P_err", "xi3_P"},
          "pore size distribution P(xi) (a density over all pores, outside the range too) and "
          "volume distribution xi^3 P(xi), at the bin centres");
  const double norm = static_cast<double>(pores_) * bin_width_;
  for (std::size_t k = 0; k < counts_.size(); ++k) {
    const double xi = (static_cast<double>(k) + 0.5) * bin_width_;
    const double p = pores_ > 0 ? counts_[k] / norm : std::nan("");
    t.add_row({xi, counts_[k], p, pores_ > 0 ? std::sqrt(counts_[k]) / norm : std::nan(""),
               xi * xi * xi * p});
  }
  return t;
}

Table PoreStatistics::bernal_table() const {
  Table t({"hole", "xi_hole", "count", "number_percent", "volume_percent", "paper_number_percent",
           "paper_volume_percent"},
          "pores nearest each Bernal canonical hole (0 tetrahedron, 1 tetragonal dodecahedron, 2 "
          "octahedron, 3 trigonal prism, 4 archimedean antiprism, 5 near none), beside Table I "
          "of Philippe & Bideau's tapping paper (paper_ columns)");
  const auto& holes = bernal_holes();
  const double nan = std::nan("");
  for (std::size_t k = 0; k < hole_counts_.size(); ++k) {
    const bool named = k < holes.size();
    const auto count = static_cast<double>(hole_counts_[k]);
    t.add_row({static_cast<double>(k), named ? holes[k].xi : nan, count,
               pores_ > 0 ? 100.0 * count / static_cast<double>(pores_) : nan,
               xi3_sum_ > 0.0 ? 100.0 * hole_volumes_[k] / xi3_sum_ : nan,
               named ? holes[k].number_percent : nan, named ? holes[k].volume_percent : nan});
  }
  return t;
}

void PoreStatistics::report(Results& results) const {
  results.add_scalar("pores", static_cast<double>(pores_), std::nan(""), "",
                     "pores counted, all frames (centres in the region)");
  results.add_scalar("spheres", static_cast<double>(spheres_), std::nan(""), "",
                     "particle centres in the region, all frames");
  results.add_scalar(
      "pores_per_sphere",
      spheres_ > 0 ? static_cast<double>(pores_) / static_cast<double>(spheres_) : std::nan(""),
      std::nan(""), "", "pores over particle centres in the region");
  results.add_scalar("nu", nu(), std::nan(""), "",
                     "nu = integral of xi^3 P(xi) = <xi^3>, over every pore counted");
  results.add_scalar("outside_histogram", static_cast<double>(outside_), std::nan(""), "",
                     "pores with xi outside the histogram's range (in P's normalisation)");
  results.add_scalar("flat_cells", static_cast<double>(flat_cells_), std::nan(""), "",
                     "Delaunay cells left out as flat within the tolerance, all frames");
  results.add_scalar("untangent_cells", static_cast<double>(untangent_cells_), std::nan(""), "",
                     "Delaunay cells of unequal spheres left out: no sphere touches their four "
                     "from outside, all frames");
  results.add_scalar("fifth_sphere_cells", static_cast<double>(fifth_sphere_cells_), std::nan(""),
                     "",
                     "Delaunay cells of unequal spheres left out: their tangent sphere overlaps a "
                     "sphere next to their four, all frames");
  results.add_scalar("apollonius_vertices", static_cast<double>(apollonius_vertices_), std::nan(""),
                     "",
                     "pores of unequal spheres that no Delaunay cell gives, found around the "
                     "cells whose tangent sphere overlaps a fifth sphere (in the region or "
                     "not), all frames");
  results.add_table("xi_distribution", distribution_table());
  results.add_plot("xi3_P", {.table = "xi_distribution",
                             .x = "xi",
                             .y = {"xi3_P"},
                             .xlabel = "xi = r/R",
                             .ylabel = "xi^3 P(xi)",
                             .title = "volume distribution of the pores"});
  results.add_table("bernal", bernal_table());
}

}  // namespace granpipe::pores
