#include "length_unit.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <utility>

namespace granpipe {

namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

std::optional<double> symbol_metres(std::string_view symbol) {
  for (std::string_view angstrom : {"A", "\u00c5", "angstrom", "Angstrom"})
    if (symbol == angstrom) return 1e-10;
  if (symbol.empty() || symbol.back() != 'm') return std::nullopt;
  symbol.remove_suffix(1);
  constexpr std::array<std::pair<std::string_view, double>, 9> kPrefixes{{{"", 1.0},
                                                                          {"k", 1e3},
                                                                          {"c", 1e-2},
                                                                          {"m", 1e-3},
                                                                          {"u", 1e-6},
                                                                          {"\u00b5", 1e-6},
                                                                          {"n", 1e-9},
                                                                          {"p", 1e-12},
                                                                          {"f", 1e-15}}};
  for (const auto& [prefix, factor] : kPrefixes)
    if (symbol == prefix) return factor;
  return std::nullopt;
}

}  // namespace

std::optional<double> metres_of(std::string_view unit) {
  unit = trimmed(unit);
  double factor = 1.0;
  const auto [end, error] = std::from_chars(unit.data(), unit.data() + unit.size(), factor);
  if (error == std::errc{}) {
    if (!(factor > 0.0) || !std::isfinite(factor)) return std::nullopt;
    unit.remove_prefix(static_cast<std::size_t>(end - unit.data()));
  } else {
    factor = 1.0;
  }
  const std::optional<double> metres = symbol_metres(trimmed(unit));
  if (!metres) return std::nullopt;
  return factor * *metres;
}

bool same_length_unit(std::string_view a, std::string_view b) {
  if (a == b) return true;
  const std::optional<double> x = metres_of(a), y = metres_of(b);
  return x && y && std::abs(*x - *y) <= 1e-12 * std::max(*x, *y);
}

}  // namespace granpipe
