#include "json_path.hpp"

#include <cctype>
#include <charconv>

#include "granpipe/errors.hpp"
#include "param_validation.hpp"
#include "strict_json.hpp"

namespace granpipe {
using json = nlohmann::json;

namespace {

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// A key in a path: a name, which may hold '-' after its start (a pair table's "small-large").
bool is_key_char(char c) { return is_name_char(c) || c == '-'; }

}  // namespace

std::vector<std::string> split_path(const std::string& path, const std::string& where) {
  const auto malformed = [&] {
    return InputError(
        where + ": expected a path like source.params.name or analyzers[0].params.name, got " +
        json_brief(path));
  };
  std::vector<std::string> parts;
  std::size_t pos = 0;
  while (pos < path.size()) {
    if (parts.size() == kMaxJsonDepth) {
      throw InputError(where + ": expected a path of at most " + std::to_string(kMaxJsonDepth) +
                       " parts, got more");
    }
    std::size_t end = pos;
    if (path[pos] == '[') {
      ++pos;
      for (end = pos; end < path.size() && is_digit(path[end]);) ++end;
      if (end == pos || end == path.size() || path[end] != ']') throw malformed();
      // [00] would name entry 0 under a second spelling, which the checks that compare
      // paths (a --set against the sweep, two swept paths) would take for another entry.
      if (end - pos > 1 && path[pos] == '0') {
        throw InputError(where + ": expected a list index without leading zeros, got [" +
                         path.substr(pos, end - pos) + "] in " + json_brief(path));
      }
      parts.push_back(path.substr(pos, end - pos));
      pos = end + 1;
      continue;
    }
    if (!parts.empty() && path[pos++] != '.') throw malformed();
    if (pos < path.size() && path[pos] == '*') {
      end = pos + 1;  // a pair table's entry for every pair
    } else {
      if (pos == path.size() || !is_name_start(path[pos])) throw malformed();
      for (end = pos + 1; end < path.size() && is_key_char(path[end]);) ++end;
    }
    parts.push_back(path.substr(pos, end - pos));
    pos = end;
  }
  if (parts.empty()) throw InputError(where + ": expected a parameter path, got \"\"");
  return parts;
}

namespace {

// "an object", "a list of 2 entries", ...: what a value is, for messages about a path.
std::string describe_kind(const json& v) {
  if (v.is_null()) return "nothing";
  if (v.is_object()) return "an object";
  if (v.is_array())
    return "a list of " + std::to_string(v.size()) + (v.size() == 1 ? " entry" : " entries");
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "true or false";
  return "a number";
}

}  // namespace

json& locate(json& root, const std::vector<std::string>& parts, const std::string& where) {
  json* node = &root;
  for (std::size_t n = 0; n < parts.size(); ++n) {
    const std::string& p = parts[n];
    const std::string before =
        join_path({parts.begin(), parts.begin() + static_cast<std::ptrdiff_t>(n)});
    const std::string at = before.empty() ? "the top" : "\"" + before + "\"";
    if (is_digit(p[0])) {
      if (!node->is_array()) {
        throw InputError(where + ": expected a list at " + at + " for [" + p + "], got " +
                         describe_kind(*node));
      }
      std::size_t k = 0;
      const auto [end, error] = std::from_chars(p.data(), p.data() + p.size(), k);
      if (error != std::errc{} || end != p.data() + p.size() || k >= node->size()) {
        throw InputError(where + ": expected an existing list entry " + before + "[" + p +
                         "], got " + describe_kind(*node));
      }
      node = &(*node)[k];
    } else {
      if (node->is_null()) *node = json::object();
      if (!node->is_object()) {
        throw InputError(where + ": expected an object at " + at + " for \"" + p + "\", got " +
                         describe_kind(*node));
      }
      node = &(*node)[p];
    }
  }
  return *node;
}

std::string join_path(const std::vector<std::string>& parts) {
  std::string path;
  for (const auto& p : parts)
    path += is_digit(p[0]) ? "[" + p + "]" : (path.empty() ? "" : ".") + p;
  return path;
}

namespace {
// Whether `s` from `pos` to its end is a parameter name, or a path into a parameter's
// value (walls.base.mu, species[1].density).
bool is_param_path_from(const std::string& s, std::size_t pos) {
  if (pos >= s.size() || !is_name_start(s[pos])) return false;
  try {
    split_path(s.substr(pos), "");
    return true;
  } catch (const InputError&) {
    return false;
  }
}
}  // namespace

bool is_plugin_param_path(const std::string& path) {
  static const std::string source = "source.params.", analyzers = "analyzers[",
                           params = "].params.";
  if (path.rfind(source, 0) == 0) return is_param_path_from(path, source.size());
  if (path.rfind(analyzers, 0) != 0) return false;
  std::size_t end = analyzers.size();
  while (end < path.size() && is_digit(path[end])) ++end;
  return end > analyzers.size() && path.compare(end, params.size(), params) == 0 &&
         is_param_path_from(path, end + params.size());
}

}  // namespace granpipe
