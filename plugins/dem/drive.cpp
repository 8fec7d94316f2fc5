#include "drive.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "granpipe/errors.hpp"

namespace granpipe::dem {

Eigen::Vector3d Drive::offset(double t) const {
  if (!moves() || t < start) return Eigen::Vector3d::Zero();
  const double phase = angular_frequency * (std::min(t, stop) - start);
  const double s = form == Form::Sine ? std::sin(phase) : 1.0 - std::cos(phase);
  return amplitude * s * direction;
}

Eigen::Vector3d Drive::velocity(double t) const {
  if (!moves() || t < start || t >= stop) return Eigen::Vector3d::Zero();
  const double phase = angular_frequency * (t - start);
  const double s = form == Form::Sine ? std::cos(phase) : std::sin(phase);
  return amplitude * angular_frequency * s * direction;
}

double Drive::cycles(double t) const {
  return std::max(0.0, std::min(t, stop) - start) * angular_frequency / (2.0 * std::numbers::pi);
}

void Drive::check() const {
  const auto finite = [](double v, const char* name) {
    if (std::isfinite(v)) return;
    std::ostringstream s;
    s << "dem: drive " << name << ": expected a finite value, got " << v;
    throw InputError(s.str());
  };
  finite(amplitude, "amplitude");
  finite(angular_frequency, "angular frequency");
  finite(start, "start");
  if (!(stop >= start)) {
    std::ostringstream s;
    s << "dem: drive stop: expected a time >= the start (" << start << "), got " << stop;
    throw InputError(s.str());
  }
  if (!direction.allFinite() || std::abs(direction.norm() - 1.0) > 1e-12) {
    std::ostringstream s;
    s << "dem: drive direction: expected a unit vector, got (" << direction.transpose() << ")";
    throw InputError(s.str());
  }
}

}  // namespace granpipe::dem
