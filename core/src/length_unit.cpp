#include "length_unit.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>
#include <vector>

#include "granpipe/text_words.hpp"

namespace granpipe {

namespace {

std::optional<double> symbol_metres(std::string_view symbol) {
  for (std::string_view angstrom : {"A", "\u00c5", "angstrom", "Angstrom"})
    if (symbol == angstrom) return 1e-10;
  if (symbol.empty() || symbol.back() != 'm') return std::nullopt;
  symbol.remove_suffix(1);
  constexpr std::array<std::pair<std::string_view, double>, 10> kPrefixes{{{"", 1.0},
                                                                           {"k", 1e3},
                                                                           {"c", 1e-2},
                                                                           {"m", 1e-3},
                                                                           {"u", 1e-6},
                                                                           {"\u00b5", 1e-6},
                                                                           {"\u03bc", 1e-6},
                                                                           {"n", 1e-9},
                                                                           {"p", 1e-12},
                                                                           {"f", 1e-15}}};
  for (const auto& [prefix, factor] : kPrefixes)
    if (symbol == prefix) return factor;
  return std::nullopt;
}

}  // namespace

std::optional<double> metres_of(std::string_view unit) {
  const std::vector<std::string_view> w = words(unit);
  if (w.empty() || w.size() > 2) return std::nullopt;
  std::string_view symbol = w.back();
  std::optional<double> factor = 1.0;
  if (w.size() == 2) {
    factor = real_number(w[0]);
  } else {  // a factor glued to the symbol: "10nm", "1e-9m", "+2nm"
    // from_chars reads no '+'; one before no number ("+m") is no factor.
    if (symbol.size() > 1 && symbol[0] == '+' &&
        (std::isdigit(static_cast<unsigned char>(symbol[1])) || symbol[1] == '.'))
      symbol.remove_prefix(1);
    double glued = 1.0;
    const auto [end, error] = std::from_chars(symbol.data(), symbol.data() + symbol.size(), glued);
    if (error == std::errc{} && end != symbol.data() + symbol.size()) {
      factor = glued;
      symbol.remove_prefix(static_cast<std::size_t>(end - symbol.data()));
    }
  }
  const std::optional<double> metres = symbol_metres(symbol);
  if (!factor || !(*factor > 0.0) || !std::isfinite(*factor) || !metres) return std::nullopt;
  return *factor * *metres;
}

bool same_length_unit(std::string_view a, std::string_view b) {
  if (a == b) return true;
  const std::optional<double> x = metres_of(a), y = metres_of(b);
  return x && y && std::abs(*x - *y) <= 1e-12 * std::max(*x, *y);
}

}  // namespace granpipe
