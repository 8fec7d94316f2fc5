#pragma once
// Validation of a JSON parameter object against a plugin's schema.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "granpipe/params.hpp"

namespace granpipe {

// Whether JSON path `outer` holds `path`: "a.b" covers "a.b", "a.b.c" and "a.b[0]", not "a.bc".
bool covers(const std::string& outer, const std::string& path);

// A value put into the pipeline after reading its file, by `--set path=value` or by a
// sweep: a message about it (or about what it holds) names its origin, not the file.
struct Override {
  std::string path;    // "source.params.radius", as JsonLocation paths read
  std::string origin;  // "--set source.params.radius=0", or "" for the file itself
  // An object the --set made on its way to its value (the file lacked it): messages about
  // it name the --set, but it is no value the --set gives.
  bool made = false;
};

// Where a JSON value sits, for error messages: "pipelines/x.json: analyzers[1].params",
// or "--set analyzers[1].params.r=0" when the last override covering it says so.
struct JsonLocation {
  std::string file;
  std::string path;
  const std::vector<Override>* overrides = nullptr;  // later ones win
  JsonLocation child(const std::string& key) const;
  JsonLocation index(std::size_t i) const;
  // An entry whose key is no name (a sweep's "source.params.n"): path["source.params.n"].
  JsonLocation quoted_key(const std::string& key) const;
  std::string str() const;
  // The --set that put the value here, or "" for the file.
  std::string origin() const;
  // str() for a key that may not be in the file: an override that set a value inside it
  // (--set source.params.walls.bse.k_n=1) made it.
  std::string key_str() const;
};

// `message` ("source.params.cells: expected ...", from a plugin) with its origin in front.
std::string located_message(const JsonLocation& top, const std::string& message);

// JSON numbers that are whole (5 or 5.0, 1e3) are integers; 5.5 and 1e30 (beyond the
// doubles that hold every integer) are not.
bool as_integer(const nlohmann::json& v, std::int64_t& out);
// Why a whole number is no integer, to follow "got ...": " (beyond 2^63 - 1, ...)", or "".
std::string why_not_integer(const nlohmann::json& v);

// Short rendering of a JSON value for "got ..." (strings quoted, long values cut).
std::string json_brief(const nlohmann::json& v);

// Refuses an `obj` that is not an object or has a key not in `allowed` (with a did-you-mean).
void check_keys(const nlohmann::json& obj, const std::vector<std::string>& allowed,
                const JsonLocation& at);

// Checks `object` against `schema` and returns the values with defaults filled in;
// `object` is rewritten to its filled-in form (what pipeline.json records). Relative
// paths are resolved against the working directory, then `base_dir`.
Params validate_params(nlohmann::json& object, const Schema& schema, const JsonLocation& where,
                       const std::filesystem::path& base_dir);

// What read_params does about a parameter the object leaves out: take its default (or
// refuse it when required), or leave it out of the result (a pair table's entries, whose
// keys "*" may give).
enum class Missing : std::uint8_t { Default, Skip };

// validate_params without the rewriting, for an object nested in the parameters.
Params read_params(const nlohmann::json& object, const Schema& schema, const JsonLocation& where,
                   const std::filesystem::path& base_dir, Missing missing = Missing::Default);

// The JSON form of parameter values (for defaults written back into the pipeline).
nlohmann::json to_json(const ParamValue& v);
nlohmann::json to_json(const Params& p);

}  // namespace granpipe
