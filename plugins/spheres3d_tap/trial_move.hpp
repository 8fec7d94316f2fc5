#pragma once
// The Monte Carlo trial displacement of the paper's Eq. (1): length uniform in
// [0, d_max], azimuth uniform in [0, 2 pi), polar angle theta from straight down with
// density P(theta) ~ exp(-(theta / theta0)^2) on [0, pi/2] - a density in theta itself,
// as Eq. (1) is written (not per solid angle, which would add a factor sin theta).
#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "granpipe/random.hpp"

namespace granpipe::spheres3d_tap {

struct TrialMove {
  double d_max = 0.2;                      // a length: the paper's R / 5 for R = 1
  double theta0 = std::numbers::pi / 4.0;  // the paper's

  // The polar angle: |normal| * theta0 / sqrt 2 has the density exp(-(theta/theta0)^2)
  // on theta >= 0; draws past pi/2 are drawn again (truncation).
  double polar(RandomStream& rng) const {
    for (;;) {
      const double theta = std::abs(rng.normal()) * theta0 / std::numbers::sqrt2;
      if (theta <= std::numbers::pi / 2.0) return theta;
    }
  }
  Eigen::Vector3d draw(RandomStream& rng) const {
    const double length = d_max * rng.uniform(), azimuth = 2.0 * std::numbers::pi * rng.uniform();
    const double theta = polar(rng), s = std::sin(theta);
    return length * Eigen::Vector3d(s * std::cos(azimuth), s * std::sin(azimuth), -std::cos(theta));
  }
};

}  // namespace granpipe::spheres3d_tap
