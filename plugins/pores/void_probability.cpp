#include "void_probability.hpp"

#include <cmath>

#include "percus_yevick.hpp"

namespace granpipe::pores {

VoidProbability::VoidProbability(double sigma_step, double sigma_max) {
  // The grid stops at sigma_max itself, a last step shorter where the step does not divide
  // it: beyond, the probes would look further than the parameter says (and its check).
  const auto steps = static_cast<long>(std::ceil(sigma_max / sigma_step - 1e-9));
  for (long k = 0; k < steps; ++k) sigma_.push_back(static_cast<double>(k) * sigma_step);
  sigma_.push_back(sigma_max);
  free_.assign(sigma_.size(), 0);
}

void VoidProbability::add(const std::vector<double>& gaps, double particle_volume,
                          double region_volume) {
  for (double gap : gaps)
    for (std::size_t k = 0; k < sigma_.size() && gap > sigma_[k]; ++k) ++free_[k];
  probes_ += static_cast<long>(gaps.size());
  particle_volume_ += particle_volume;
  region_volume_ += region_volume;
}

double VoidProbability::phi() const {
  return region_volume_ > 0.0 ? particle_volume_ / region_volume_ : std::nan("");
}

Table VoidProbability::table() const {
  Table t({"sigma", "P0", "P0_err", "P0_py"},
          "probability P0 that a probe sphere of radius sigma R at a random point of the region "
          "overlaps no sphere (Monte Carlo, binomial error) and the Percus-Yevick prediction at "
          "the region's packing fraction");
  const auto n = static_cast<double>(probes_);
  for (std::size_t k = 0; k < sigma_.size(); ++k) {
    const double p = probes_ > 0 ? static_cast<double>(free_[k]) / n : std::nan("");
    t.add_row({sigma_[k], p, std::sqrt(p * (1.0 - p) / n), p0_percus_yevick(phi(), sigma_[k])});
  }
  return t;
}

void VoidProbability::report(Results& results) const {
  results.add_scalar("probes", static_cast<double>(probes_), std::nan(""), "",
                     "random probes of P0, all frames");
  results.add_scalar("phi", phi(), std::nan(""), "",
                     "packing fraction of the probes' region (exact particle volume in it)");
  results.add_table("p0", table());
  results.add_plot("P0", {.table = "p0",
                          .x = "sigma",
                          .y = {"P0", "P0_py"},
                          .xlabel = "sigma = probe radius / R",
                          .ylabel = "P0(sigma)",
                          .title = "probability that a probe overlaps no sphere"});
}

}  // namespace granpipe::pores
