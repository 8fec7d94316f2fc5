#include "trial_move.hpp"

#include <cmath>
#include <vector>

namespace granpipe::spheres3d_tap {

TrialMove::TrialMove(double d_max, double theta0) : d_max_(d_max), theta0_(theta0) {
  for (int k = 0; k < kSectors; ++k) table_[k] = {std::sin(k * kStep), std::cos(k * kStep)};
  for (int k = 0; k <= kStrips; ++k) density_[k] = density(k * kStep);
  // Vose's construction of the alias table for strip weights density_[k] (equal widths).
  double total = 0.0;
  for (int k = 0; k < kStrips; ++k) total += density_[k];
  std::array<double, kStrips> scaled;
  std::vector<int> small, large;
  for (int k = 0; k < kStrips; ++k) {
    scaled[k] = density_[k] * kStrips / total;
    (scaled[k] < 1.0 ? small : large).push_back(k);
  }
  while (!small.empty() && !large.empty()) {
    const int s = small.back(), l = large.back();
    small.pop_back();
    keep_[s] = scaled[s];
    alias_[s] = l;
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // What is left has weight 1 up to rounding: always kept.
  for (const std::vector<int>* rest : {&small, &large}) {
    for (int k : *rest) {
      keep_[k] = 1.0;
      alias_[k] = k;
    }
  }
}

double TrialMove::density(double theta) const {
  const double t = theta / theta0_;
  return std::exp(-t * t);
}

}  // namespace granpipe::spheres3d_tap
