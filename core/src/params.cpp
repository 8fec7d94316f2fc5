#include "granpipe/params.hpp"

#include <cmath>
#include <memory>
#include <type_traits>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "param_tables.hpp"
#include "param_validation.hpp"

namespace granpipe {

const char* to_string(ParamType t) {
  switch (t) {
    case ParamType::Bool:
      return "bool";
    case ParamType::Int:
      return "integer";
    case ParamType::Real:
      return "number";
    case ParamType::String:
      return "string";
    case ParamType::Choice:
      return "choice";
    case ParamType::Path:
      return "path";
    case ParamType::PathList:
      return "list of paths";
    case ParamType::IntList:
      return "list of integers";
    case ParamType::RealList:
      return "list of numbers";
    case ParamType::Object:
      return "object";
    case ParamType::Species:
      return "species table";
    case ParamType::Pairs:
      return "pair table";
  }
  return "?";
}

Schema::Entry Schema::add(ParamSpec spec) {
  if (find(spec.name)) throw InternalError("schema declares parameter '" + spec.name + "' twice");
  specs_.push_back(std::move(spec));
  return Entry(specs_.back());
}

namespace {
ParamSpec new_spec(const std::string& name, ParamType type, const std::string& doc) {
  ParamSpec s;
  s.name = name;
  s.type = type;
  s.doc = doc;
  return s;
}
}  // namespace

Schema::Entry Schema::boolean(const std::string& name, bool def, const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::Bool, doc);
  s.default_value = def;
  return add(std::move(s));
}

Schema::Entry Schema::integer(const std::string& name, std::optional<std::int64_t> def,
                              const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::Int, doc);
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::real(const std::string& name, std::optional<double> def,
                           const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::Real, doc);
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::string(const std::string& name, std::optional<std::string> def,
                             const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::String, doc);
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::add_choice(const std::string& name, std::vector<std::string> choices,
                                 std::optional<std::string> def, const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::Choice, doc);
  s.choices = std::move(choices);
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::path(const std::string& name, std::optional<std::string> def,
                           const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::Path, doc);
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::paths(const std::string& name, std::optional<std::vector<std::string>> def,
                            const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::PathList, doc);
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::integers(const std::string& name,
                               std::optional<std::vector<std::int64_t>> def,
                               const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::IntList, doc);
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::reals(const std::string& name, std::optional<std::vector<double>> def,
                            const std::string& doc) {
  ParamSpec s = new_spec(name, ParamType::RealList, doc);
  if (def) s.default_value = *def;
  return add(std::move(s));
}

namespace {
// The runner checks path parameters against the output directory, and sees only the top
// level of a schema.
void refuse_nested_paths(const Schema& fields, const std::string& name) {
  for (const auto& f : fields.specs()) {
    if (f.type == ParamType::Path || f.type == ParamType::PathList) {
      throw InternalError("schema: '" + name + "' holds the path parameter '" + f.name +
                          "'; paths are top-level parameters only");
    }
    if (f.fields) refuse_nested_paths(*f.fields, name);
  }
}
}  // namespace

Schema::Entry Schema::object(const std::string& name, Schema fields, const std::string& doc) {
  refuse_nested_paths(fields, name);
  ParamSpec s = new_spec(name, ParamType::Object, doc);
  s.fields = std::make_shared<const Schema>(std::move(fields));
  return add(std::move(s));
}

Schema::Entry Schema::species_table(const std::string& name, Schema fields,
                                    std::optional<std::string> default_json,
                                    const std::string& doc) {
  refuse_nested_paths(fields, name);
  if (fields.find("name")) {
    throw InternalError("schema: species table '" + name +
                        "' declares 'name', which every species has");
  }
  Schema species;
  species.string("name", std::nullopt, "the species' name (a letter, then letters, digits and _)");
  for (auto& f : fields.specs_) species.add(std::move(f));
  ParamSpec s = new_spec(name, ParamType::Species, doc);
  s.fields = std::make_shared<const Schema>(std::move(species));
  s.default_json = std::move(default_json);
  check_table_default(s, *this);
  return add(std::move(s));
}

Schema::Entry Schema::pair_table(const std::string& name, const std::string& species, Schema fields,
                                 std::optional<std::string> default_json, const std::string& doc) {
  refuse_nested_paths(fields, name);
  const ParamSpec* table = find(species);
  if (!table || table->type != ParamType::Species) {
    throw InternalError("schema: pair table '" + name + "' names '" + species +
                        "', which is not a species table declared before it");
  }
  ParamSpec s = new_spec(name, ParamType::Pairs, doc);
  s.fields = std::make_shared<const Schema>(std::move(fields));
  s.species = species;
  s.default_json = std::move(default_json);
  check_table_default(s, *this);
  return add(std::move(s));
}

const ParamSpec* Schema::find(const std::string& name) const {
  for (const auto& s : specs_)
    if (s.name == name) return &s;
  return nullptr;
}

const ParamValue& Params::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw InternalError("parameter '" + name + "' is not in the schema");
  return it->second;
}

template <class T>
static const T& typed(const ParamValue& v, const std::string& name, const char* type) {
  if (const T* p = std::get_if<T>(&v)) return *p;
  throw InternalError("parameter '" + name + "' read as " + type + " but declared otherwise");
}

bool Params::boolean(const std::string& n) const { return typed<bool>(get(n), n, "bool"); }
std::int64_t Params::integer(const std::string& n) const {
  return typed<std::int64_t>(get(n), n, "integer");
}
double Params::real(const std::string& n) const {
  const ParamValue& v = get(n);
  // An integer-typed value is never stored for a Real spec; validation converts.
  return typed<double>(v, n, "number");
}
const std::string& Params::string(const std::string& n) const {
  return typed<std::string>(get(n), n, "string");
}
const std::vector<std::int64_t>& Params::integers(const std::string& n) const {
  return typed<std::vector<std::int64_t>>(get(n), n, "list of integers");
}
const std::vector<double>& Params::reals(const std::string& n) const {
  return typed<std::vector<double>>(get(n), n, "list of numbers");
}
const std::vector<std::string>& Params::paths(const std::string& n) const {
  return typed<std::vector<std::string>>(get(n), n, "list of paths");
}
const Params& Params::object(const std::string& n) const {
  return *typed<std::shared_ptr<const Params>>(get(n), n, "object");
}
const SpeciesTable& Params::species(const std::string& n) const {
  return *typed<std::shared_ptr<const SpeciesTable>>(get(n), n, "species table");
}
const PairTable& Params::pairs(const std::string& n) const {
  return *typed<std::shared_ptr<const PairTable>>(get(n), n, "pair table");
}

namespace {
// 15 digits: a value as the pipeline gave it (0.1, not 0.10000000000000001).
std::string number(double x) { return format_number(x, 15); }
template <class T>
std::string list(const std::vector<T>& v) {
  std::string out = "[";
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (k) out += ", ";
    out += number(static_cast<double>(v[k]));
  }
  return out + "]";
}
}  // namespace

std::string format_value(const ParamValue& v) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, bool>)
          return x ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::int64_t>)
          return std::to_string(x);
        else if constexpr (std::is_same_v<T, double>)
          return number(x);
        else if constexpr (std::is_same_v<T, std::string>)
          return "\"" + x + "\"";
        else if constexpr (std::is_same_v<T, std::vector<std::int64_t>> ||
                           std::is_same_v<T, std::vector<double>>)
          return list(x);
        else if constexpr (std::is_same_v<T, std::vector<std::string>>)
          return nlohmann::json(x).dump();
        else
          return to_json(x).dump();
      },
      v);
}

bool optional_path(const ParamSpec& spec) {
  if (spec.type != ParamType::Path || !spec.default_value) return false;
  const auto* text = std::get_if<std::string>(&*spec.default_value);
  return text && text->empty();
}

std::string describe_expected(const ParamSpec& spec) {
  std::string what;
  switch (spec.type) {
    case ParamType::Bool:
      return "true or false";
    case ParamType::Int:
      what = "an integer";
      break;
    case ParamType::Real:
      what = "a number";
      break;
    case ParamType::String:
      return "a string";
    case ParamType::Path:
      return optional_path(spec) ? "a path to an existing file, or \"\" for none"
                                 : "a path to an existing file";
    case ParamType::PathList:
      return "a list of paths to existing files";
    case ParamType::Choice: {
      what = "one of ";
      for (std::size_t k = 0; k < spec.choices.size(); ++k)
        what += (k ? ", \"" : "\"") + spec.choices[k] + "\"";
      return what;
    }
    case ParamType::Object:
      return "an object";
    case ParamType::Species:
      return "a list of species, each an object with a \"name\"";
    case ParamType::Pairs:
      return "an object with a key \"a-b\" per pair of " + spec.species +
             " (\"*\": the pairs not listed)";
    case ParamType::IntList:
    case ParamType::RealList:
      what = spec.list_length ? "a list of " + std::to_string(*spec.list_length) + " "
             : spec.max_list_length
                 ? "a list of at most " + std::to_string(*spec.max_list_length) + " "
                 : std::string("a list of ");
      what += spec.type == ParamType::IntList ? "integers" : "numbers";
      break;
  }
  if (spec.min && spec.max && !spec.min_exclusive && !spec.max_exclusive) {
    what += " in [" + number(*spec.min) + ", " + number(*spec.max) + "]";
  } else {
    if (spec.min) what += std::string(spec.min_exclusive ? " > " : " >= ") + number(*spec.min);
    if (spec.min && spec.max) what += " and";
    if (spec.max) what += std::string(spec.max_exclusive ? " < " : " <= ") + number(*spec.max);
  }
  return what;
}

}  // namespace granpipe
