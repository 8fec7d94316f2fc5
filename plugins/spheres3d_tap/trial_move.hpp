#pragma once
// The Monte Carlo trial displacement of the paper's Eq. (1): length uniform in
// [0, d_max], azimuth uniform in [0, 2 pi), polar angle theta from straight down with
// density P(theta) ~ exp(-(theta / theta0)^2) on [0, pi/2] - a density in theta itself,
// as Eq. (1) is written (not per solid angle, which would add a factor sin theta).
//
// Drawn exactly but without a transcendental call in the common path: sincos and the
// normal draw were a sixth of a trial move's time. The polar angle is drawn by rejection
// under a step envelope (64 strips, the envelope at each strip's left edge since the
// density falls; a strip picked by Walker's alias method, a point in it accepted at once
// below the strip's right-edge value, else against exp: about 2 % of draws rejected).
// Sines and cosines of both angles come from a table at multiples of pi/128 and the
// addition formulas, with Taylor series for the remainder below pi/128, whose
// truncation (< 1e-17) is below double rounding.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <numbers>

namespace granpipe::spheres3d_tap {

class TrialMove {
 public:
  TrialMove() : TrialMove(0.2, std::numbers::pi / 4.0) {}
  // d_max a length (the paper's R / 5), theta0 in radians (the paper's pi / 4).
  TrialMove(double d_max, double theta0);

  double d_max() const { return d_max_; }
  double theta0() const { return theta0_; }

  template <class Rng>
  double polar(Rng& rng) const {
    const Angle a = draw_polar(rng);
    return a.step * kStep + a.rest;
  }
  template <class Rng>
  Eigen::Vector3d draw(Rng& rng) const {
    const double length = d_max_ * rng.uniform();
    const Angle azimuth = draw_azimuth(rng), theta = draw_polar(rng);
    const SinCos phi = sincos(azimuth), pol = sincos(theta);
    return length * Eigen::Vector3d(pol.sin * phi.cos, pol.sin * phi.sin, -pol.cos);
  }

 private:
  static constexpr int kStrips = 64;    // polar strips on [0, pi/2]
  static constexpr int kSectors = 256;  // azimuth sectors on [0, 2 pi)
  static constexpr double kStep = std::numbers::pi / 128.0;
  static constexpr std::uint64_t kMantissa = (std::uint64_t{1} << 53) - 1;

  // step * kStep + rest, 0 <= rest < kStep.
  struct Angle {
    int step;
    double rest;
  };
  struct SinCos {
    double sin, cos;
  };
  static double fraction(std::uint64_t bits) {
    return static_cast<double>(bits & kMantissa) * 0x1.0p-53;
  }
  template <class Rng>
  Angle draw_azimuth(Rng& rng) const {
    const std::uint64_t b = rng.bits();
    return {static_cast<int>(b >> 56), fraction(b) * kStep};
  }
  template <class Rng>
  Angle draw_polar(Rng& rng) const {
    for (;;) {
      const std::uint64_t b = rng.bits();
      int k = static_cast<int>(b >> 58);
      if (fraction(b) >= keep_[k]) k = alias_[k];
      const double rest = rng.uniform() * kStep, v = rng.uniform() * density_[k];
      if (v <= density_[k + 1] || v <= density(k * kStep + rest)) return {k, rest};
    }
  }
  double density(double theta) const;
  // Inline: its multiplications then overlap the trial's wait for memory.
  SinCos sincos(Angle a) const {
    // Multiplications by the reciprocals (divisions would cost as much as the rest); their
    // rounding touches only terms below 1e-3 of the result.
    constexpr double k2 = 1.0 / 2.0, k6 = 1.0 / 6.0, k12 = 1.0 / 12.0, k20 = 1.0 / 20.0,
                     k30 = 1.0 / 30.0, k42 = 1.0 / 42.0;
    const double d = a.rest, d2 = d * d;
    const double s = d * (1.0 - d2 * k6 * (1.0 - d2 * k20 * (1.0 - d2 * k42)));
    const double c = 1.0 - d2 * k2 * (1.0 - d2 * k12 * (1.0 - d2 * k30));
    const SinCos& t = table_[a.step];
    return {t.sin * c + t.cos * s, t.cos * c - t.sin * s};
  }

  double d_max_, theta0_;
  std::array<double, kStrips + 1> density_;  // at the strip edges
  std::array<double, kStrips> keep_;         // Walker's alias table of the strips
  std::array<int, kStrips> alias_;
  std::array<SinCos, kSectors> table_;  // at multiples of kStep
};

}  // namespace granpipe::spheres3d_tap
