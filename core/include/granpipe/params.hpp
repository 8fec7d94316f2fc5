#pragma once
// Parameter schemas and validated parameter values. Plugins declare a Schema; the core
// validates the pipeline's JSON against it and hands the plugin a Params object.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "granpipe/errors.hpp"

namespace granpipe {

enum class ParamType : std::uint8_t {
  Bool,
  Int,
  Real,
  String,
  Choice,
  Path,
  PathList,  // a list of paths to existing files
  IntList,
  RealList,
  Object,   // an object with its own schema
  Species,  // a list of species objects, each named
  Pairs,    // an object of species-pair objects, keyed "a-b" (and "*" for the others)
};
const char* to_string(ParamType t);

class Params;
class Schema;
class SpeciesTable;
class PairTable;

using ParamValue =
    std::variant<bool, std::int64_t, double, std::string, std::vector<std::int64_t>,
                 std::vector<double>, std::vector<std::string>, std::shared_ptr<const Params>,
                 std::shared_ptr<const SpeciesTable>, std::shared_ptr<const PairTable>>;

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Real;
  std::optional<ParamValue> default_value;  // none: the parameter is required
  std::optional<double> min, max;           // inclusive bounds on numbers and list elements
  bool min_exclusive = false, max_exclusive = false;
  std::vector<std::string> choices;            // for Choice
  std::optional<std::size_t> list_length;      // exact length of a list, if fixed
  std::optional<std::size_t> max_list_length;  // the longest a list may be, if bounded
  std::string unit;                            // "" for dimensionless
  std::string doc;                             // one line
  std::shared_ptr<const Schema> fields;        // Object, Species, Pairs: the schema of each object
  std::string species;                         // Pairs: the Species parameter its keys name
  std::optional<std::string> default_json;     // Species, Pairs: the default, as JSON text
  // Where the parameter has an effect (empty: everywhere) and that place in words
  // ("region inner"): elsewhere a value other than the default is refused, as a mistyped
  // parameter is, rather than ignored.
  std::function<bool(const Params&)> applies;
  std::string applies_where;
};

// The names a pipeline gives the values of an enum, declared once beside the enum (found
// by argument-dependent lookup) and used by Schema::choice<E> and Params::choice<E>:
//   enum class Order { Sweeps, Random };
//   inline granpipe::ChoiceNames<Order> choice_names(Order) {
//     return {{"sweeps", Order::Sweeps}, {"random", Order::Random}};
//   }
template <class E>
using ChoiceNames = std::vector<std::pair<std::string, E>>;

// The name of an enum value, e.g. for a message.
template <class E>
std::string choice_name(E value) {
  for (const auto& [name, e] : choice_names(E{}))
    if (e == value) return name;
  throw InternalError("an enum value has no name in its choice_names");
}

// A fluent builder keeps plugin schemas to one readable line per parameter.
class Schema {
 public:
  class Entry {
   public:
    explicit Entry(ParamSpec& s) : s_(s) {}
    Entry& range(double lo, double hi) {
      s_.min = lo;
      s_.max = hi;
      return *this;
    }
    Entry& min(double lo, bool exclusive = false) {
      s_.min = lo;
      s_.min_exclusive = exclusive;
      return *this;
    }
    Entry& max(double hi, bool exclusive = false) {
      s_.max = hi;
      s_.max_exclusive = exclusive;
      return *this;
    }
    Entry& unit(std::string u) {
      s_.unit = std::move(u);
      return *this;
    }
    Entry& max_length(std::size_t n) {
      s_.max_list_length = n;
      return *this;
    }
    Entry& length(std::size_t n) {
      s_.list_length = n;
      return *this;
    }
    // The parameter acts only `where` (in words, "probes > 0") `applies` holds.
    Entry& only_where(std::string where, std::function<bool(const Params&)> applies) {
      if (!s_.default_value)
        throw InternalError("only_where on parameter '" + s_.name + "', which has no default");
      s_.applies_where = std::move(where);
      s_.applies = std::move(applies);
      return *this;
    }

   private:
    ParamSpec& s_;
  };

  Entry boolean(const std::string& name, bool def, const std::string& doc);
  Entry integer(const std::string& name, std::optional<std::int64_t> def, const std::string& doc);
  Entry real(const std::string& name, std::optional<double> def, const std::string& doc);
  Entry string(const std::string& name, std::optional<std::string> def, const std::string& doc);
  // One of the names of choice_names(E), read back with Params::choice<E>.
  template <class E>
  Entry choice(const std::string& name, std::optional<E> def, const std::string& doc) {
    std::vector<std::string> names;
    for (const auto& entry : choice_names(E{})) names.push_back(entry.first);
    return add_choice(name, std::move(names), def ? std::optional(choice_name(*def)) : std::nullopt,
                      doc);
  }
  // A file that must exist when the pipeline is validated.
  Entry path(const std::string& name, std::optional<std::string> def, const std::string& doc);
  // Files that must exist, in a list (which may be empty).
  Entry paths(const std::string& name, std::optional<std::vector<std::string>> def,
              const std::string& doc);
  Entry integers(const std::string& name, std::optional<std::vector<std::int64_t>> def,
                 const std::string& doc);
  Entry reals(const std::string& name, std::optional<std::vector<double>> def,
              const std::string& doc);

  // An object whose keys `fields` declares, e.g. "walls": {"base": {"k_n": ...}}. Left
  // out, it is {} (its fields' defaults).
  Entry object(const std::string& name, Schema fields, const std::string& doc);
  // A list of species, [{"name": "small", <fields>}, ...]: each entry has a unique name and
  // the keys `fields` declares; a species' index is its place in the list.
  // `default_json` (JSON text) is used when the pipeline leaves the parameter out.
  Entry species_table(const std::string& name, Schema fields,
                      std::optional<std::string> default_json, const std::string& doc);
  // Values for every pair of the species of `species` (a species_table declared before):
  // {"*": {<fields>}, "small-large": {<fields>}}. A pair's keys override "*"'s, "*"'s
  // override the defaults of `fields`; a-b is b-a.
  Entry pair_table(const std::string& name, const std::string& species, Schema fields,
                   std::optional<std::string> default_json, const std::string& doc);

  const std::vector<ParamSpec>& specs() const { return specs_; }
  const ParamSpec* find(const std::string& name) const;

 private:
  Entry add(ParamSpec spec);
  Entry add_choice(const std::string& name, std::vector<std::string> choices,
                   std::optional<std::string> def, const std::string& doc);
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
  const std::vector<std::string>& paths(const std::string& name) const;
  template <class E>
  E choice(const std::string& name) const {
    const std::string& value = string(name);
    for (const auto& [n, e] : choice_names(E{}))
      if (n == value) return e;
    throw InternalError("parameter '" + name + "' holds \"" + value +
                        "\", not one of its choice_names");
  }
  const Params& object(const std::string& name) const;
  const SpeciesTable& species(const std::string& name) const;
  const PairTable& pairs(const std::string& name) const;
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  const std::map<std::string, ParamValue>& values() const { return values_; }

 private:
  const ParamValue& get(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
};

// The species of a Schema::species_table, in the pipeline's order.
class SpeciesTable {
 public:
  explicit SpeciesTable(std::vector<Params> species) : species_(std::move(species)) {}
  std::size_t size() const { return species_.size(); }
  const Params& operator[](std::size_t i) const { return species_.at(i); }
  const std::string& name(std::size_t i) const { return species_.at(i).string("name"); }
  std::optional<std::size_t> find(const std::string& name) const;
  // A number field of every species, by index (e.g. the diameters).
  std::vector<double> reals(const std::string& field) const;

 private:
  std::vector<Params> species_;
};

// A pair coefficient as an S x S symmetric matrix, laid out for a force loop.
class PairMatrix {
 public:
  PairMatrix(std::size_t species, std::vector<double> values)
      : species_(species), values_(std::move(values)) {}
  std::size_t species() const { return species_; }
  double operator()(std::size_t i, std::size_t j) const { return values_[i * species_ + j]; }
  const double* data() const { return values_.data(); }  // row-major

 private:
  std::size_t species_;
  std::vector<double> values_;
};

// The values of a Schema::pair_table for every pair of species (i, j), with i-j == j-i.
class PairTable {
 public:
  // `pairs`: (0,0), (0,1), ..., (0,S-1), (1,1), ..., (S-1,S-1) of the named species.
  PairTable(std::vector<std::string> species, std::vector<Params> pairs);
  std::size_t size() const { return species_.size(); }  // of species
  const std::vector<std::string>& species() const { return species_; }
  const Params& at(std::size_t i, std::size_t j) const;
  std::string key(std::size_t i, std::size_t j) const;  // "small-large"
  // A number field of every pair.
  PairMatrix matrix(const std::string& field) const;

 private:
  std::vector<std::string> species_;
  std::vector<Params> pairs_;
};

// Human-readable form of a value, as in error messages and `granpipe describe`.
std::string format_value(const ParamValue& v);
// What a spec accepts, e.g. "a number in [0, 1]" or "one of \"sc\", \"fcc\"".
std::string describe_expected(const ParamSpec& spec);
// A path parameter whose default is "" (no file): "" is then a value it takes.
bool optional_path(const ParamSpec& spec);

}  // namespace granpipe
