#pragma once
// The arithmetic the contact evaluator is written in, for one contact (ScalarMath: a
// double and a padded Vec4, the wall path) or one contact per lane (LaneMath: the pair
// loop, at the instruction set's width). Each backend maps an operation to what its path
// computed before the evaluator was shared, so both paths keep their results to the bit.
#include <cmath>

#include "lanes.hpp"
#include "vec4.hpp"

namespace granpipe::dem {

struct ScalarMath {
  using Real = double;
  using Vec = Vec4;
  using Mask = bool;

  static Real splat(double x) { return x; }
  static Real dot(const Vec& a, const Vec& b) { return a.dot(b); }
  static Vec cross(const Vec& a, const Vec& b) { return dem::cross(a, b); }
  static Real sqrt(Real x) { return std::sqrt(x); }
  static Real abs(Real x) { return std::abs(x); }
  static Vec divide(const Vec& a, Real s) { return a / s; }
  static Vec select(Mask m, const Vec& a, const Vec& b) { return m ? a : b; }
};

struct LaneMath {
  using Real = lanes::Reals;
  using Vec = lanes::Vec;
  using Mask = decltype(Real{} < Real{});

  static Real splat(double x) { return lanes::splat(x); }
  static Real dot(const Vec& a, const Vec& b) { return lanes::dot(a, b); }
  static Vec cross(const Vec& a, const Vec& b) { return lanes::cross(a, b); }
  static Real sqrt(const Real& x) { return lanes::sqrt(x); }
  static Real abs(const Real& x) { return lanes::abs(x); }
  static Vec divide(const Vec& a, const Real& s) { return {a.x / s, a.y / s, a.z / s}; }
  static Vec select(const Mask& m, const Vec& a, const Vec& b) { return lanes::select(m, a, b); }
};

}  // namespace granpipe::dem
