#include "granpipe/params.hpp"

#include <cmath>
#include <sstream>

#include "granpipe/errors.hpp"

namespace granpipe {

const char* to_string(ParamType t) {
  switch (t) {
    case ParamType::Bool: return "bool";
    case ParamType::Int: return "integer";
    case ParamType::Real: return "number";
    case ParamType::String: return "string";
    case ParamType::Choice: return "choice";
    case ParamType::Path: return "path";
    case ParamType::IntList: return "list of integers";
    case ParamType::RealList: return "list of numbers";
  }
  return "?";
}

Schema::Entry Schema::add(ParamSpec spec) {
  if (find(spec.name)) throw InternalError("schema declares parameter '" + spec.name + "' twice");
  specs_.push_back(std::move(spec));
  return Entry(specs_.back());
}

Schema::Entry Schema::boolean(const std::string& name, bool def, const std::string& doc) {
  return add({name, ParamType::Bool, ParamValue(def), {}, {}, false, false, {}, {}, "", doc});
}

Schema::Entry Schema::integer(const std::string& name, std::optional<std::int64_t> def,
                              const std::string& doc) {
  ParamSpec s{name, ParamType::Int, {}, {}, {}, false, false, {}, {}, "", doc};
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::real(const std::string& name, std::optional<double> def,
                           const std::string& doc) {
  ParamSpec s{name, ParamType::Real, {}, {}, {}, false, false, {}, {}, "", doc};
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::string(const std::string& name, std::optional<std::string> def,
                             const std::string& doc) {
  ParamSpec s{name, ParamType::String, {}, {}, {}, false, false, {}, {}, "", doc};
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::choice(const std::string& name, std::vector<std::string> choices,
                             std::optional<std::string> def, const std::string& doc) {
  ParamSpec s{name, ParamType::Choice, {}, {}, {}, false, false, std::move(choices), {}, "", doc};
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::path(const std::string& name, std::optional<std::string> def,
                           const std::string& doc) {
  ParamSpec s{name, ParamType::Path, {}, {}, {}, false, false, {}, {}, "", doc};
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::integers(const std::string& name,
                               std::optional<std::vector<std::int64_t>> def,
                               const std::string& doc) {
  ParamSpec s{name, ParamType::IntList, {}, {}, {}, false, false, {}, {}, "", doc};
  if (def) s.default_value = *def;
  return add(std::move(s));
}

Schema::Entry Schema::reals(const std::string& name, std::optional<std::vector<double>> def,
                            const std::string& doc) {
  ParamSpec s{name, ParamType::RealList, {}, {}, {}, false, false, {}, {}, "", doc};
  if (def) s.default_value = *def;
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

namespace {
std::string number(double x) {
  std::ostringstream s;
  s.precision(15);
  s << x;
  return s.str();
}
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
        if constexpr (std::is_same_v<T, bool>) return x ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::int64_t>) return std::to_string(x);
        else if constexpr (std::is_same_v<T, double>) return number(x);
        else if constexpr (std::is_same_v<T, std::string>) return "\"" + x + "\"";
        else return list(x);
      },
      v);
}

std::string describe_expected(const ParamSpec& spec) {
  std::string what;
  switch (spec.type) {
    case ParamType::Bool: return "true or false";
    case ParamType::Int: what = "an integer"; break;
    case ParamType::Real: what = "a number"; break;
    case ParamType::String: return "a string";
    case ParamType::Path: return "a path to an existing file";
    case ParamType::Choice: {
      what = "one of ";
      for (std::size_t k = 0; k < spec.choices.size(); ++k)
        what += (k ? ", \"" : "\"") + spec.choices[k] + "\"";
      return what;
    }
    case ParamType::IntList:
    case ParamType::RealList:
      what = spec.list_length ? "a list of " + std::to_string(*spec.list_length) + " "
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
