// Reading a pipeline: JSON parsing with line/column errors, --set overrides, the
// top-level schema, the plugins' parameter schemas, and sweep expansion.
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "did_you_mean.hpp"
#include "granpipe/plugin_loader.hpp"
#include "param_validation.hpp"
#include "pipeline_impl.hpp"

namespace granpipe {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

json parse_json(const std::string& text, const std::string& origin) {
  try {
    return json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    std::size_t line = 1, col = 1;
    for (std::size_t k = 0; k + 1 < e.byte && k < text.size(); ++k) {
      if (text[k] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    std::string reason = e.what();
    const auto colon = reason.find(": ", reason.find("parse error"));
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    throw InputError(origin + ":" + std::to_string(line) + ":" + std::to_string(col) +
                     ": malformed JSON: " + reason);
  }
}

void check_keys(const json& obj, const std::vector<std::string>& allowed, const JsonLocation& at) {
  if (!obj.is_object()) throw InputError(at.str() + ": expected an object, got " + json_brief(obj));
  for (const auto& [key, v] : obj.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw InputError(at.child(key).str() + ": unknown key" + did_you_mean(key, allowed) +
                       known_list(allowed));
    }
  }
}

// "a.b[2].c" -> JSON pointer parts.
std::vector<std::string> split_path(const std::string& path, const std::string& where) {
  static const std::regex token(R"(([A-Za-z_][A-Za-z0-9_]*)|\[(\d+)\])");
  std::vector<std::string> parts;
  std::size_t pos = 0;
  while (pos < path.size()) {
    if (path[pos] == '.' && pos > 0) ++pos;
    std::smatch m;
    std::string rest = path.substr(pos);
    if (!std::regex_search(rest, m, token, std::regex_constants::match_continuous)) {
      throw InputError(where + ": expected a path like source.params.name or analyzers[0].params.name, got \"" +
                       path + "\"");
    }
    parts.push_back(m[1].matched ? m[1].str() : m[2].str());
    pos += m.length(0);
  }
  if (parts.empty()) throw InputError(where + ": expected a parameter path, got \"\"");
  return parts;
}

json& locate(json& root, const std::vector<std::string>& parts, const std::string& where) {
  json* node = &root;
  for (const auto& p : parts) {
    if (!p.empty() && std::isdigit(static_cast<unsigned char>(p[0]))) {
      const std::size_t k = std::stoul(p);
      if (!node->is_array() || k >= node->size()) {
        throw InputError(where + ": expected an existing list entry [" + p + "], got none");
      }
      node = &(*node)[k];
    } else {
      if (node->is_null()) *node = json::object();
      if (!node->is_object()) throw InputError(where + ": expected an object at \"" + p + "\"");
      node = &(*node)[p];
    }
  }
  return *node;
}

void apply_set(json& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  const std::string where = "--set " + assignment;
  if (eq == std::string::npos) throw InputError(where + ": expected path=value, got no '='");
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  json value;
  try {
    value = json::parse(text);
  } catch (const json::parse_error&) {
    value = text;  // a bare word is a string: --set source.params.lattice=fcc
  }
  locate(root, split_path(path, where), where) = value;
}

std::uint64_t read_seed(const json& root, const JsonLocation& at) {
  if (!root.contains("seed")) return 1;
  const json& s = root["seed"];
  if (!s.is_number_unsigned() && !(s.is_number_integer() && s.get<std::int64_t>() >= 0)) {
    throw InputError(at.child("seed").str() + ": expected an integer >= 0, got " + json_brief(s));
  }
  return s.get<std::uint64_t>();
}

// Each sweep point as {path: value}: grid = cartesian product, zip = element-wise.
std::vector<json> expand_sweep(const json& sweep, const JsonLocation& at,
                               std::vector<std::string>& paths) {
  check_keys(sweep, {"mode", "parameters"}, at);
  const bool mode_is_string = !sweep.contains("mode") || sweep["mode"].is_string();
  const std::string mode = mode_is_string ? sweep.value("mode", "grid") : "";
  if (mode != "grid" && mode != "zip") {
    throw InputError(at.child("mode").str() + ": expected one of \"grid\", \"zip\", got " +
                     json_brief(sweep["mode"]));
  }
  const JsonLocation pat = at.child("parameters");
  if (!sweep.contains("parameters") || !sweep["parameters"].is_object() || sweep["parameters"].empty()) {
    throw InputError(pat.str() + ": expected an object of \"path\": [values...], got " +
                     (sweep.contains("parameters") ? json_brief(sweep["parameters"]) : "nothing"));
  }
  std::vector<const json*> lists;
  for (const auto& [path, values] : sweep["parameters"].items()) {
    if (!values.is_array() || values.empty()) {
      throw InputError(pat.str() + "[\"" + path + "\"]: expected a non-empty list of values, got " +
                       json_brief(values));
    }
    static const std::regex param_path(R"((source|analyzers\[\d+\])\.params\.[A-Za-z_]\w*)");
    if (!std::regex_match(path, param_path)) {
      throw InputError(pat.str() + "[\"" + path + "\"]: expected a plugin parameter path like "
                       "source.params.name or analyzers[0].params.name, got \"" + path + "\"");
    }
    paths.push_back(path);
    lists.push_back(&values);
  }
  std::vector<json> points;
  if (mode == "zip") {
    for (std::size_t k = 1; k < lists.size(); ++k) {
      if (lists[k]->size() != lists[0]->size()) {
        throw InputError(pat.str() + "[\"" + paths[k] + "\"]: expected " +
                         std::to_string(lists[0]->size()) + " values (zip mode), got " +
                         std::to_string(lists[k]->size()));
      }
    }
    for (std::size_t i = 0; i < lists[0]->size(); ++i) {
      json p = json::object();
      for (std::size_t k = 0; k < lists.size(); ++k) p[paths[k]] = (*lists[k])[i];
      points.push_back(p);
    }
  } else {
    points.push_back(json::object());
    for (std::size_t k = 0; k < lists.size(); ++k) {
      std::vector<json> next;
      for (const auto& p : points)
        for (const auto& v : *lists[k]) {
          json q = p;
          q[paths[k]] = v;
          next.push_back(q);
        }
      points = std::move(next);
    }
  }
  return points;
}

}  // namespace

Pipeline::Pipeline(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

Pipeline Pipeline::load(const fs::path& file, const std::vector<std::string>& sets,
                        const Registry& registry) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError(file.string() + ": expected a pipeline JSON file, got " +
                     (fs::exists(file) ? "a file that cannot be read" : "no such file"));
  }
  std::stringstream ss;
  ss << in.rdbuf();
  Pipeline p = parse(ss.str(), file.string(), sets, registry);
  p.impl_->base_dir = file.parent_path();
  p.impl_->file = file;
  return p;
}

Pipeline Pipeline::parse(const std::string& text, const std::string& origin,
                         const std::vector<std::string>& sets, const Registry& registry) {
  json root = parse_json(text, origin);
  const JsonLocation top{origin, ""};
  if (!root.is_object()) throw InputError(origin + ": expected a JSON object, got " + json_brief(root));
  for (const auto& s : sets) apply_set(root, s);
  check_keys(root, {"name", "description", "seed", "source", "analyzers", "output", "sweep"}, top);

  auto impl = std::make_unique<Impl>();
  impl->origin = origin;
  impl->base_dir = fs::path(origin).parent_path();
  for (const char* key : {"name", "description"}) {
    if (root.contains(key) && !root[key].is_string()) {
      throw InputError(top.child(key).str() + ": expected a string, got " + json_brief(root[key]));
    }
  }
  impl->name = root.value("name", fs::path(origin).stem().string());
  impl->description = root.value("description", "");
  impl->seed = read_seed(root, top);
  root["name"] = impl->name;
  root["seed"] = impl->seed;

  const JsonLocation src_at = top.child("source");
  if (!root.contains("source")) throw InputError(src_at.str() + ": expected a source, got nothing");
  check_keys(root["source"], {"plugin", "params"}, src_at);
  if (!root["source"].contains("plugin") || !root["source"]["plugin"].is_string()) {
    throw InputError(src_at.child("plugin").str() + ": expected a plugin name, got " +
                     json_brief(root["source"].value("plugin", json())));
  }
  impl->source = &require_plugin(registry, root["source"]["plugin"], PluginKind::Source,
                                 src_at.child("plugin").str());

  const JsonLocation an_at = top.child("analyzers");
  if (!root.contains("analyzers")) root["analyzers"] = json::array();
  if (!root["analyzers"].is_array()) {
    throw InputError(an_at.str() + ": expected a list of analyzers, got " + json_brief(root["analyzers"]));
  }
  std::set<std::string> names;
  for (std::size_t k = 0; k < root["analyzers"].size(); ++k) {
    json& a = root["analyzers"][k];
    const JsonLocation at = an_at.index(k);
    check_keys(a, {"plugin", "name", "params"}, at);
    if (!a.contains("plugin") || !a["plugin"].is_string()) {
      throw InputError(at.child("plugin").str() + ": expected a plugin name, got " +
                       json_brief(a.value("plugin", json())));
    }
    AnalyzerSpec spec;
    spec.info = &require_plugin(registry, a["plugin"], PluginKind::Analyzer, at.child("plugin").str());
    if (a.contains("name")) {
      // The name becomes an HDF5 group and a file name: keep it plain, and clear of the
      // runner's own groups.
      static const std::regex plain("[A-Za-z][A-Za-z0-9_]*");
      const json& n = a["name"];
      if (!n.is_string() || !std::regex_match(n.get<std::string>(), plain) || n == "source" ||
          n == "sweep" || n.get<std::string>().rfind("point_", 0) == 0) {
        throw InputError(at.child("name").str() +
                         ": expected a name of letters, digits and _ (not source, sweep or point_*), got " +
                         json_brief(n));
      }
    }
    spec.name = a.value("name", spec.info->name);
    spec.where = at.str();
    if (!names.insert(spec.name).second) {
      throw InputError(at.child("name").str() + ": expected a name not used by another analyzer, got \"" +
                       spec.name + "\" again");
    }
    a["name"] = spec.name;
    impl->analyzers.push_back(spec);
  }

  const JsonLocation out_at = top.child("output");
  if (!root.contains("output")) root["output"] = json::object();
  json& out = root["output"];
  check_keys(out, {"dir", "save_frames", "frame_stride"}, out_at);
  if (out.contains("dir") && (!out["dir"].is_string() || out["dir"].get<std::string>().empty()))
    throw InputError(out_at.child("dir").str() + ": expected a directory path, got " + json_brief(out["dir"]));
  if (out.contains("save_frames") && !out["save_frames"].is_boolean())
    throw InputError(out_at.child("save_frames").str() + ": expected true or false, got " +
                     json_brief(out["save_frames"]));
  if (out.contains("frame_stride") &&
      (!out["frame_stride"].is_number_integer() || out["frame_stride"].get<std::int64_t>() < 1))
    throw InputError(out_at.child("frame_stride").str() + ": expected an integer >= 1, got " +
                     json_brief(out["frame_stride"]));
  impl->output_dir = out.value("dir", "out/" + impl->name);
  impl->save_frames = out.value("save_frames", true);
  impl->frame_stride = out.value("frame_stride", std::int64_t{1});
  out["dir"] = impl->output_dir.string();
  out["save_frames"] = impl->save_frames;
  out["frame_stride"] = impl->frame_stride;

  std::vector<json> assignments{json::object()};
  if (root.contains("sweep")) assignments = expand_sweep(root["sweep"], top.child("sweep"), impl->sweep_paths);

  for (std::size_t k = 0; k < assignments.size(); ++k) {
    PointSpec point;
    point.assignment = assignments[k];
    json p = root;
    p.erase("sweep");
    std::string note;
    for (const auto& [path, value] : assignments[k].items()) {
      locate(p, split_path(path, "sweep"), top.child("sweep").str()) = value;
      note += (note.empty() ? " (sweep point " + std::to_string(k) + ": " : ", ") + path + " = " +
              json_brief(value);
    }
    if (!note.empty()) note += ")";
    try {
      point.source_params = validate_params(p["source"]["params"], impl->source->schema,
                                            src_at.child("params"), impl->base_dir);
      for (std::size_t a = 0; a < impl->analyzers.size(); ++a) {
        point.analyzer_params.push_back(validate_params(p["analyzers"][a]["params"],
                                                        impl->analyzers[a].info->schema,
                                                        an_at.index(a).child("params"), impl->base_dir));
      }
    } catch (const InputError& e) {
      throw InputError(e.what() + note);
    }
    point.resolved = p;
    impl->points.push_back(std::move(point));
  }
  impl->resolved = impl->points.front().resolved;
  if (root.contains("sweep")) impl->resolved["sweep"] = root["sweep"];
  return Pipeline(std::move(impl));
}

std::string Pipeline::resolved_json() const { return impl_->resolved.dump(2); }
std::size_t Pipeline::points() const { return impl_->points.size(); }
std::uint64_t Pipeline::seed() const { return impl_->seed; }

}  // namespace granpipe
