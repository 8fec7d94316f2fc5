#pragma once
// Parameter schemas and validated parameter values. Plugins declare a Schema; the core
// validates the pipeline's JSON against it and hands the plugin a Params object.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace granpipe {

enum class ParamType : std::uint8_t { Bool, Int, Real, String, Choice, Path, IntList, RealList };
const char* to_string(ParamType t);

using ParamValue = std::variant<bool, std::int64_t, double, std::string, std::vector<std::int64_t>,
                                std::vector<double>>;

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Real;
  std::optional<ParamValue> default_value;  // none: the parameter is required
  std::optional<double> min, max;           // inclusive bounds on numbers and list elements
  bool min_exclusive = false, max_exclusive = false;
  std::vector<std::string> choices;         // for Choice
  std::optional<std::size_t> list_length;   // exact length of a list, if fixed
  std::string unit;                         // "" for dimensionless
  std::string doc;                          // one line
};

// A fluent builder keeps plugin schemas to one readable line per parameter.
class Schema {
 public:
  class Entry {
   public:
    explicit Entry(ParamSpec& s) : s_(s) {}
    Entry& range(double lo, double hi) { s_.min = lo; s_.max = hi; return *this; }
    Entry& min(double lo, bool exclusive = false) { s_.min = lo; s_.min_exclusive = exclusive; return *this; }
    Entry& max(double hi, bool exclusive = false) { s_.max = hi; s_.max_exclusive = exclusive; return *this; }
    Entry& unit(std::string u) { s_.unit = std::move(u); return *this; }
    Entry& length(std::size_t n) { s_.list_length = n; return *this; }
   private:
    ParamSpec& s_;
  };

  Entry boolean(const std::string& name, bool def, const std::string& doc);
  Entry integer(const std::string& name, std::optional<std::int64_t> def, const std::string& doc);
  Entry real(const std::string& name, std::optional<double> def, const std::string& doc);
  Entry string(const std::string& name, std::optional<std::string> def, const std::string& doc);
  Entry choice(const std::string& name, std::vector<std::string> choices,
               std::optional<std::string> def, const std::string& doc);
  // A file that must exist when the pipeline is validated.
  Entry path(const std::string& name, std::optional<std::string> def, const std::string& doc);
  Entry integers(const std::string& name, std::optional<std::vector<std::int64_t>> def,
                 const std::string& doc);
  Entry reals(const std::string& name, std::optional<std::vector<double>> def,
              const std::string& doc);

  const std::vector<ParamSpec>& specs() const { return specs_; }
  const ParamSpec* find(const std::string& name) const;

 private:
  Entry add(ParamSpec spec);
  std::vector<ParamSpec> specs_;
};

// Validated values of every parameter in a schema (defaults filled in).
class Params {
 public:
  Params() = default;
  explicit Params(std::map<std::string, ParamValue> values) : values_(std::move(values)) {}

  bool boolean(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  double real(const std::string& name) const;
  const std::string& string(const std::string& name) const;  // String, Choice and Path
  const std::vector<std::int64_t>& integers(const std::string& name) const;
  const std::vector<double>& reals(const std::string& name) const;
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  const std::map<std::string, ParamValue>& values() const { return values_; }

 private:
  const ParamValue& get(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
};

// Human-readable form of a value, as in error messages and `granpipe describe`.
std::string format_value(const ParamValue& v);
// What a spec accepts, e.g. "a number in [0, 1]" or "one of \"sc\", \"fcc\"".
std::string describe_expected(const ParamSpec& spec);

}  // namespace granpipe
