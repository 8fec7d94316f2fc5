#include "length_unit.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include "granpipe/text_words.hpp"

namespace granpipe {

namespace {

// The metre's prefixes, as symbols ("nm") and written out ("nanometre").
struct Prefix {
  std::string_view symbol, name;
  double factor;
};
constexpr std::array<Prefix, 10> kPrefixes{{{"", "", 1.0},
                                            {"k", "kilo", 1e3},
                                            {"c", "centi", 1e-2},
                                            {"m", "milli", 1e-3},
                                            {"u", "micro", 1e-6},
                                            {"\u00b5", "micro", 1e-6},
                                            {"\u03bc", "micro", 1e-6},
                                            {"n", "nano", 1e-9},
                                            {"p", "pico", 1e-12},
                                            {"f", "femto", 1e-15}}};

// A unit's name written out ("nanometer", "micrometres", as MDAnalysis and others write
// them), or nothing.
std::optional<double> named_metres(std::string_view name) {
  if (name.size() > 1 && name.back() == 's') name.remove_suffix(1);  // plural
  for (std::string_view metre : {"meter", "metre"}) {
    if (!name.ends_with(metre)) continue;
    const std::string_view prefix = name.substr(0, name.size() - metre.size());
    for (const Prefix& p : kPrefixes)
      if (prefix == p.name) return p.factor;
  }
  return std::nullopt;
}

std::optional<double> symbol_metres(std::string_view symbol) {
  // H5MD writes a unit's power after it ("nm+2" an area): a length's is 1.
  if (symbol.size() > 2 && symbol.substr(symbol.size() - 2) == "+1") symbol.remove_suffix(2);
  for (std::string_view angstrom :
       {"A", "\u00c5", "angstrom", "Angstrom", "angstroms", "Angstroms"})
    if (symbol == angstrom) return 1e-10;
  if (const std::optional<double> named = named_metres(symbol)) return named;
  if (symbol.empty() || symbol.back() != 'm') return std::nullopt;
  symbol.remove_suffix(1);
  for (const Prefix& p : kPrefixes)
    if (symbol == p.symbol) return p.factor;
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
    // from_chars reads "nan" and "inf" too: "nanometer" is no factor of "ometer".
    const bool number = !symbol.empty() && (std::isdigit(static_cast<unsigned char>(symbol[0])) ||
                                            symbol[0] == '.' || symbol[0] == '-');
    double glued = 1.0;
    const auto [end, error] = std::from_chars(symbol.data(), symbol.data() + symbol.size(), glued);
    if (number && error == std::errc{} && end != symbol.data() + symbol.size()) {
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
