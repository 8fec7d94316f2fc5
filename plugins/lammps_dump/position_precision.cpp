#include "position_precision.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace granpipe::lammps_dump {

PrintedDigits printed_digits(std::string_view word) {
  if (!word.empty() && (word[0] == '-' || word[0] == '+')) word.remove_prefix(1);
  const std::size_t e = word.find_first_of("eE");
  const std::string_view mantissa = word.substr(0, e);
  int power = 0;
  if (e != std::string_view::npos) {
    std::string_view tail = word.substr(e + 1);
    if (!tail.empty() && tail[0] == '+') tail.remove_prefix(1);
    std::from_chars(tail.data(), tail.data() + tail.size(), power);
  }
  const std::size_t point = std::min(mantissa.find('.'), mantissa.size());
  const std::size_t first = mantissa.find_first_of("123456789");
  if (first == std::string_view::npos) return {};
  int significant = 0;
  for (std::size_t k = first; k < mantissa.size(); ++k)
    if (mantissa[k] != '.') ++significant;
  // Digits left of the point count up from 10^0, right of it down from 10^-1.
  const int place =
      first < point ? static_cast<int>(point - first) - 1 : -static_cast<int>(first - point);
  return {significant, place + power};
}

double printed_rounding(std::string_view word) {
  const PrintedDigits d = printed_digits(word);
  return d.significant == 0 ? 0.0 : 0.5 * std::pow(10.0, d.exponent - d.significant + 1);
}

void PositionPrecision::add(int axis, std::string_view word) {
  const PrintedDigits d = printed_digits(word);
  if (d.significant == 0) return;
  significant_ = std::max(significant_, d.significant);
  exponent_[axis] = std::max(exponent_[axis], d.exponent);
}

std::array<double, 3> PositionPrecision::rounding(const std::array<double, 3>& scale) const {
  std::array<double, 3> r{};
  for (int a = 0; a < 3; ++a) {
    if (exponent_[a] == INT_MIN) continue;  // every value zero: exact
    r[a] = 0.5 * std::pow(10.0, exponent_[a] - significant_ + 1) * scale[a];
  }
  return r;
}

}  // namespace granpipe::lammps_dump
