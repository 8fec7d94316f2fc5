#pragma once
// Validation of a JSON parameter object against a plugin's schema.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "granpipe/params.hpp"

namespace granpipe {

// Where a JSON value sits, for error messages: "pipelines/x.json: analyzers[1].params".
struct JsonLocation {
  std::string file;
  std::string path;
  JsonLocation child(const std::string& key) const;
  JsonLocation index(std::size_t i) const;
  std::string str() const { return file + ": " + path; }
};

// Short rendering of a JSON value for "got ..." (strings quoted, long values cut).
std::string json_brief(const nlohmann::json& v);

// Checks `object` against `schema` and returns the values with defaults filled in;
// `object` is rewritten to its filled-in form (what pipeline.json records). Relative
// paths are resolved against the working directory, then `base_dir`.
Params validate_params(nlohmann::json& object, const Schema& schema, const JsonLocation& where,
                       const std::filesystem::path& base_dir);

// The JSON form of a parameter value (for defaults written back into the pipeline).
nlohmann::json to_json(const ParamValue& v);

}  // namespace granpipe
