#include "param_validation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <type_traits>

#include "did_you_mean.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/file_kind.hpp"
#include "param_tables.hpp"

namespace granpipe {

JsonLocation JsonLocation::child(const std::string& key) const {
  return {file, path.empty() ? key : path + "." + key, overrides};
}

JsonLocation JsonLocation::index(std::size_t i) const {
  return {file, path + "[" + std::to_string(i) + "]", overrides};
}

JsonLocation JsonLocation::quoted_key(const std::string& key) const {
  return {file, path + "[" + json_brief(key) + "]", overrides};
}

bool as_integer(const nlohmann::json& v, std::int64_t& out) {
  // Above 2^63 - 1 a JSON integer is stored unsigned, and would wrap to a negative.
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > std::numeric_limits<std::int64_t>::max())
    return false;
  if (v.is_number_integer()) {
    out = v.get<std::int64_t>();
    return true;
  }
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (std::isfinite(d) && std::floor(d) == d && std::fabs(d) < 9.0e15) {
      out = static_cast<std::int64_t>(d);
      return true;
    }
  }
  return false;
}

bool covers(const std::string& outer, const std::string& path) {
  return path.compare(0, outer.size(), outer) == 0 &&
         (path.size() == outer.size() || path[outer.size()] == '.' || path[outer.size()] == '[');
}

std::string JsonLocation::str() const {
  if (overrides) {
    for (auto o = overrides->rbegin(); o != overrides->rend(); ++o) {
      if (!covers(o->path, path)) continue;
      if (o->origin.empty()) break;
      return path == o->path && !o->made ? o->origin : o->origin + ": " + path;
    }
  }
  return file + ": " + path;
}

std::string JsonLocation::origin() const {
  if (overrides) {
    for (auto o = overrides->rbegin(); o != overrides->rend(); ++o)
      if (covers(o->path, path)) return o->origin;
  }
  return "";
}

std::string JsonLocation::key_str() const {
  if (overrides) {
    for (auto o = overrides->rbegin(); o != overrides->rend(); ++o) {
      if (covers(o->path, path)) break;  // str() says who set the key itself
      if (covers(path, o->path) && !o->origin.empty()) return o->origin + ": " + path;
    }
  }
  return str();
}

std::string located_message(const JsonLocation& top, const std::string& message) {
  const auto colon = message.find(": ");
  if (colon == std::string::npos) return top.str() + message;
  return top.child(message.substr(0, colon)).str() + message.substr(colon);
}

std::string json_brief(const nlohmann::json& v) {
  std::string s = v.dump();
  if (s.size() > 60) s = s.substr(0, 57) + (v.is_string() ? "...\"" : "...");
  return s;
}

nlohmann::json to_json(const Params& p) {
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [name, value] : p.values()) object[name] = to_json(value);
  return object;
}

nlohmann::json to_json(const ParamValue& v) {
  return std::visit(
      [](const auto& x) -> nlohmann::json {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, std::shared_ptr<const Params>>) {
          return to_json(*x);
        } else if constexpr (std::is_same_v<T, std::shared_ptr<const SpeciesTable>>) {
          nlohmann::json list = nlohmann::json::array();
          for (std::size_t i = 0; i < x->size(); ++i) list.push_back(to_json((*x)[i]));
          return list;
        } else if constexpr (std::is_same_v<T, std::shared_ptr<const PairTable>>) {
          nlohmann::json pairs = nlohmann::json::object();
          for (std::size_t i = 0; i < x->size(); ++i)
            for (std::size_t j = i; j < x->size(); ++j) pairs[x->key(i, j)] = to_json(x->at(i, j));
          return pairs;
        } else {
          return nlohmann::json(x);
        }
      },
      v);
}

// "expected an integer >= 1, got 1e+19" left the reader to guess.
std::string why_not_integer(const nlohmann::json& v) {
  if (v.is_number_unsigned() &&
      v.get<std::uint64_t>() > std::uint64_t{std::numeric_limits<std::int64_t>::max()})
    return " (beyond 2^63 - 1, the largest integer)";
  if (!v.is_number_float()) return "";
  const double d = v.get<double>();
  return std::isfinite(d) && std::floor(d) == d && std::fabs(d) >= 9.0e15
             ? " (with a point or an exponent a number is an exact integer only below 9e15; "
               "write larger ones in digits)"
             : "";
}

namespace {

// key_str: a --set of one entry of a list (cells[1]=0) is named, not the file.
[[noreturn]] void fail(const JsonLocation& at, const ParamSpec& spec, const nlohmann::json& got) {
  const bool integer = spec.type == ParamType::Int || spec.type == ParamType::IntList;
  throw InputError(at.key_str() + ": expected " + describe_expected(spec) + ", got " +
                   json_brief(got) + (integer ? why_not_integer(got) : ""));
}

bool in_range(const ParamSpec& s, double x) {
  if (s.min && (s.min_exclusive ? !(x > *s.min) : !(x >= *s.min))) return false;
  if (s.max && (s.max_exclusive ? !(x < *s.max) : !(x <= *s.max))) return false;
  return true;
}

// A path as the user gave it, resolved against the working directory, then `base_dir`.
std::string existing_file(const nlohmann::json& v, const JsonLocation& at,
                          const std::filesystem::path& base_dir) {
  std::filesystem::path p = v.get<std::string>();
  if (p.is_relative() && !anything_at(p) && anything_at(base_dir / p)) p = base_dir / p;
  if (!regular_file_at(p)) {
    throw InputError(at.str() + ": expected an existing file, got " + json_brief(v) + " (" +
                     what_is_at(p) + ")");
  }
  return p.string();
}

// `earlier`: the values read before this one in its object (a pair table's species).
ParamValue convert(const nlohmann::json& v, const ParamSpec& s, const JsonLocation& at,
                   const std::filesystem::path& base_dir,
                   const std::map<std::string, ParamValue>& earlier) {
  switch (s.type) {
    case ParamType::Object:
      return std::make_shared<const Params>(read_params(v, *s.fields, at, base_dir));
    case ParamType::Species:
      return read_species_table(v, s, at, base_dir);
    case ParamType::Pairs:
      return read_pair_table(v, s,
                             *std::get<std::shared_ptr<const SpeciesTable>>(earlier.at(s.species)),
                             at, base_dir);
    case ParamType::Bool:
      if (!v.is_boolean()) fail(at, s, v);
      return v.get<bool>();
    case ParamType::Int: {
      std::int64_t k;
      if (!as_integer(v, k) || !in_range(s, static_cast<double>(k))) fail(at, s, v);
      return k;
    }
    case ParamType::Real: {
      if (!v.is_number() || !std::isfinite(v.get<double>()) || !in_range(s, v.get<double>()))
        fail(at, s, v);
      return v.get<double>();
    }
    case ParamType::String:
      if (!v.is_string()) fail(at, s, v);
      return v.get<std::string>();
    case ParamType::Choice: {
      if (!v.is_string()) fail(at, s, v);
      const auto x = v.get<std::string>();
      for (const auto& c : s.choices)
        if (c == x) return x;
      throw InputError(at.str() + ": expected " + describe_expected(s) + ", got " + json_brief(v) +
                       did_you_mean(x, s.choices));
    }
    case ParamType::Path:
      if (!v.is_string()) fail(at, s, v);
      // An optional path's "" (no file) is its default, as the run's pipeline.json records it.
      if (v.get<std::string>().empty() && optional_path(s)) return std::string();
      if (v.get<std::string>().empty()) fail(at, s, v);
      return existing_file(v, at, base_dir);
    case ParamType::PathList: {
      if (!v.is_array()) fail(at, s, v);
      std::vector<std::string> files;
      for (std::size_t k = 0; k < v.size(); ++k) {
        if (!v[k].is_string() || v[k].get<std::string>().empty()) fail(at.index(k), s, v[k]);
        files.push_back(existing_file(v[k], at.index(k), base_dir));
      }
      return files;
    }
    case ParamType::IntList:
    case ParamType::RealList: {
      if (!v.is_array() || (s.list_length && v.size() != *s.list_length) ||
          (s.max_list_length && v.size() > *s.max_list_length))
        fail(at, s, v);
      std::vector<std::int64_t> ints;
      std::vector<double> reals;
      for (const auto& e : v) {
        std::int64_t k;
        if (s.type == ParamType::IntList) {
          if (!as_integer(e, k) || !in_range(s, static_cast<double>(k))) fail(at, s, v);
          ints.push_back(k);
        } else {
          if (!e.is_number() || !std::isfinite(e.get<double>()) || !in_range(s, e.get<double>()))
            fail(at, s, v);
          reals.push_back(e.get<double>());
        }
      }
      if (s.type == ParamType::IntList) return ints;
      return reals;
    }
  }
  throw InternalError("unknown parameter type");
}

}  // namespace

void check_keys(const nlohmann::json& obj, const std::vector<std::string>& allowed,
                const JsonLocation& at) {
  if (!obj.is_object()) throw InputError(at.str() + ": expected an object, got " + json_brief(obj));
  for (const auto& [key, v] : obj.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw InputError(at.child(key).key_str() + ": unknown key" + did_you_mean(key, allowed) +
                       known_list(allowed));
    }
  }
}

namespace {

// What a parameter left out stands for when it has no plain default: an object's {} (its
// fields' defaults), a table's default.
std::optional<nlohmann::json> implied_json(const ParamSpec& s) {
  if (s.type == ParamType::Object) return nlohmann::json::object();
  if (s.default_json) return nlohmann::json::parse(*s.default_json);
  return std::nullopt;
}

}  // namespace

namespace {

// "; here region is "all"" when the condition starts with a parameter's name: the value
// that made the given one useless may come from elsewhere (a --set, a sweep's point).
std::string mode_here(const std::string& applies_where, const Params& params) {
  const std::string mode = applies_where.substr(0, applies_where.find(' '));
  if (!params.has(mode)) return "";
  return "; here " + mode + " is " + format_value(params.values().at(mode));
}

// A value given where its parameter does nothing (a margin for region all) was ignored
// without a word; the default itself is let be, so that a sweep may zip it with the mode.
void refuse_what_has_no_effect(const nlohmann::json& object, const Schema& schema,
                               const Params& params, const JsonLocation& where) {
  for (const auto& s : schema.specs()) {
    if (!s.applies || !object.contains(s.name) || !s.default_value) continue;
    if (params.values().at(s.name) == *s.default_value || s.applies(params)) continue;
    throw InputError(where.child(s.name).str() + ": expected its default " +
                     format_value(*s.default_value) + " (it acts only with " + s.applies_where +
                     mode_here(s.applies_where, params) + "), got " + json_brief(object[s.name]));
  }
}

}  // namespace

Params read_params(const nlohmann::json& object, const Schema& schema, const JsonLocation& where,
                   const std::filesystem::path& base_dir, Missing missing) {
  if (!object.is_object()) {
    throw InputError(where.str() + ": expected an object of parameters, got " + json_brief(object));
  }
  std::vector<std::string> known;
  for (const auto& s : schema.specs()) known.push_back(s.name);
  for (const auto& [key, value] : object.items()) {
    if (!schema.find(key)) {
      throw InputError(where.child(key).key_str() + ": unknown parameter" +
                       did_you_mean(key, known) + known_list(known));
    }
  }
  std::map<std::string, ParamValue> values;
  for (const auto& s : schema.specs()) {
    const JsonLocation at = where.child(s.name);
    if (object.contains(s.name)) {
      values[s.name] = convert(object[s.name], s, at, base_dir, values);
    } else if (missing == Missing::Skip) {
      continue;
    } else if (s.default_value) {
      values[s.name] = *s.default_value;
    } else if (const auto def = implied_json(s)) {
      values[s.name] = convert(*def, s, at, base_dir, values);
    } else {
      throw InputError(at.str() + ": expected " + describe_expected(s) +
                       ", got nothing (required)");
    }
  }
  Params params(std::move(values));
  if (missing != Missing::Skip) refuse_what_has_no_effect(object, schema, params, where);
  return params;
}

Params validate_params(nlohmann::json& object, const Schema& schema, const JsonLocation& where,
                       const std::filesystem::path& base_dir) {
  if (object.is_null()) object = nlohmann::json::object();
  Params params = read_params(object, schema, where, base_dir);
  object = to_json(params);
  return params;
}

}  // namespace granpipe
