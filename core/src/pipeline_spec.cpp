// Reading a pipeline: JSON parsing with line/column errors, --set overrides, the
// top-level schema, the plugins' parameter schemas, and sweep expansion.
#include <charconv>
#include <cstdio>
#include <fstream>
#include <set>

#include "granpipe/file_kind.hpp"
#include "granpipe/plugin_loader.hpp"
#include "json_path.hpp"
#include "names.hpp"
#include "param_validation.hpp"
#include "pipeline_impl.hpp"
#include "report_spec.hpp"
#include "strict_json.hpp"
#include "sweep.hpp"

namespace granpipe {

std::string sweep_point_note(const PointSpec& point, std::size_t k) {
  std::string note;
  for (const auto& [path, value] : point.assignment.items())
    note += (note.empty() ? " (sweep point " + std::to_string(k) + ": " : ", ") + path + " = " +
            json_brief(value);
  return note.empty() ? note : note + ")";
}
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// Far more than the longest sweep list needs; a bound on what reading a file may take.
constexpr std::size_t kMaxPipelineBytes = std::size_t{64} << 20;

// "--set a=b", cut short if long, to start a message about that --set.
std::string set_origin(const std::string& assignment) {
  return "--set " + (assignment.size() > 80 ? assignment.substr(0, 77) + "..." : assignment);
}

// A --set goes into the pipeline's JSON, whose keys and strings are UTF-8.
void check_utf8(const std::string& assignment) {
  const std::size_t bad = first_invalid_utf8(assignment);
  if (bad == std::string::npos) return;
  char byte[8];
  std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(assignment[bad]));
  throw InputError(set_origin(assignment.substr(0, bad)) +
                   "...: expected UTF-8 text, got the byte " + byte + " next");
}

// Where a --set writes, and the path its override is known by in messages. A sweep's
// parameter names are themselves paths ("source.params.epsilon"), so what follows
// sweep.parameters is one key (--set sweep.parameters.source.params.epsilon=[0.1] cuts the
// file's sweep to one value rather than nesting objects the sweep cannot read), named as the
// sweep names its entries so that its messages name the --set.
struct SetTarget {
  std::vector<std::string> parts;
  std::string path;
};

SetTarget set_target(const std::vector<std::string>& parts) {
  if (parts.size() < 3 || parts[0] != "sweep" || parts[1] != "parameters")
    return {parts, join_path(parts)};
  const std::string key = join_path({parts.begin() + 2, parts.end()});
  return {{"sweep", "parameters", key}, JsonLocation{"", "sweep.parameters"}.quoted_key(key).path};
}

// How many of `parts` lead through values `root` already has.
std::size_t existing_depth(const json& root, const std::vector<std::string>& parts) {
  const json* node = &root;
  std::size_t n = 0;
  for (; n < parts.size(); ++n) {
    const std::string& p = parts[n];
    std::size_t k = 0;
    if (node->is_object() && node->contains(p)) {
      node = &(*node)[p];
    } else if (node->is_array() &&
               std::from_chars(p.data(), p.data() + p.size(), k).ec == std::errc{} &&
               k < node->size()) {
      node = &(*node)[k];
    } else {
      break;
    }
  }
  return n;
}

// Applies `--set path=value` and says where the value came from, and where it made the
// objects leading to it: a message about such an object (contacts made by --set
// contacts.small-large.mu=0.1 lacking its other pairs) named the file, which has none.
std::vector<Override> apply_set(json& root, const std::string& assignment) {
  check_utf8(assignment);
  const auto eq = assignment.find('=');
  const std::string where = set_origin(assignment);
  if (eq == std::string::npos) throw InputError(where + ": expected path=value, got no '='");
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  const SetTarget target = set_target(split_path(path, where));
  // A bare word is a string: --set source.params.lattice=fcc
  const json value =
      parse_strict_json_if_json(text, where, target.parts.size()).value_or(json(text));
  const std::size_t depth = existing_depth(root, target.parts);
  locate(root, target.parts, where) = value;
  std::vector<Override> overrides;
  if (depth + 1 < target.parts.size()) {
    overrides.push_back({join_path({target.parts.begin(),
                                    target.parts.begin() + static_cast<std::ptrdiff_t>(depth) + 1}),
                         where, true});
  }
  overrides.push_back({target.path, where});
  return overrides;
}

// Two --set of one value ran with the last, without a word, where a sweep refuses the same
// (a script adding its --set to a user's ran with the script's); so did a --set of what
// holds a value another --set gave before it, which it replaced. A value set inside what a
// --set before it made (writers=[...] then writers[0].name=...) is how such a value is
// given: both hold.
void refuse_sets_of_one_value(const std::vector<Override>& sets) {
  for (std::size_t b = 1; b < sets.size(); ++b) {
    for (std::size_t a = 0; a < b; ++a) {
      if (sets[a].made || sets[b].made) continue;
      const std::string &first = sets[a].path, &second = sets[b].path;
      if (!covers(second, first)) continue;  // second neither is first nor holds it
      const std::string what = first == second ? second : second + ", which holds " + first;
      throw InputError(sets[b].origin + ": expected a value no other --set gives, got " + what +
                       ", which " + sets[a].origin + " sets too");
    }
  }
}

// A --set of a parameter the sweep sets at every point was dropped without a word (the run
// went on with the sweep's values, the pipeline.json recording none of the --set's).
void refuse_sets_the_sweep_replaces(const std::vector<Override>& sets,
                                    const std::vector<std::string>& sweep_paths) {
  for (const Override& set : sets) {
    for (const std::string& swept : sweep_paths) {
      if (set.origin.empty() || set.made) continue;
      // A --set of the object holding a swept value (--set source.params={...}) is
      // replaced there too, in part.
      const bool holds = covers(set.path, swept) && set.path != swept;
      if (!holds && !covers(swept, set.path)) continue;
      throw InputError(set.origin + ": expected a value the sweep leaves alone, got " +
                       (holds ? set.path + ", which holds " + swept : swept) +
                       ", which the sweep sets at every point; give the sweep the values " +
                       "instead: --set 'sweep.parameters." + swept + "=[...]'");
    }
  }
}

std::uint64_t read_seed(const json& root, const JsonLocation& at) {
  if (!root.contains("seed")) return 1;
  const json& s = root["seed"];
  if (s.is_number_unsigned()) return s.get<std::uint64_t>();
  // Whole numbers as plugins' integer parameters take them (1e3, 64.0).
  std::int64_t whole = 0;
  if (!as_integer(s, whole) || whole < 0) {
    throw InputError(at.child("seed").str() + ": expected an integer >= 0, got " + json_brief(s));
  }
  return static_cast<std::uint64_t>(whole);
}

}  // namespace

Pipeline::Pipeline(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

Pipeline Pipeline::load(const fs::path& file, const std::vector<std::string>& sets,
                        const Registry& registry) {
  const std::string expected = file.string() + ": expected a pipeline JSON file";
  if (!regular_file_at(file)) throw InputError(expected + ", got " + what_is_at(file));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(expected + ", got a file that cannot be read");
  // Read in chunks up to one byte past the limit: a longer file (or /dev/zero) is
  // known without reading it all.
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= kMaxPipelineBytes && in.read(chunk, sizeof chunk).gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (text.size() > kMaxPipelineBytes) {
    throw InputError(expected + " of at most " + std::to_string(kMaxPipelineBytes >> 20) +
                     " MB, got a longer one");
  }
  Pipeline p = parse(text, file.string(), sets, registry);
  p.impl_->base_dir = file.parent_path();
  p.impl_->file = file;
  return p;
}

namespace {

// An analyzer's "publish": true (the default) or false.
bool read_publish(json& entry, const JsonLocation& at) {
  if (!entry.contains("publish")) return true;
  if (!entry["publish"].is_boolean()) {
    throw InputError(at.child("publish").str() + ": expected true or false, got " +
                     json_brief(entry["publish"]));
  }
  return entry["publish"].get<bool>();
}

// A plugin's "params" is an object, or left out. Checked before a sweep assigns into it, so
// that the --set or file line that put something else there is named, not the sweep.
void require_params_object(const json& entry, const JsonLocation& at) {
  if (!entry.contains("params") || entry["params"].is_null() || entry["params"].is_object()) {
    return;
  }
  throw InputError(at.child("params").str() + ": expected an object of parameters, got " +
                   json_brief(entry["params"]));
}

// The analyzers or writers of a pipeline ("analyzers": [{"plugin": ..., "name": ...,
// "publish": ..., "params": {...}}, ...]), each name unique among both (the files they
// write start with it); only analyzers publish.
std::vector<PluginSpec> parse_plugin_list(json& root, const std::string& key, PluginKind kind,
                                          const JsonLocation& top, const Registry& registry,
                                          std::set<std::string>& names) {
  const JsonLocation list_at = top.child(key);
  if (!root.contains(key)) root[key] = json::array();
  if (!root[key].is_array()) {
    throw InputError(list_at.str() + ": expected a list of " + key + ", got " +
                     json_brief(root[key]));
  }
  std::vector<PluginSpec> specs;
  for (std::size_t k = 0; k < root[key].size(); ++k) {
    json& a = root[key][k];
    const JsonLocation at = list_at.index(k);
    const bool analyzer = kind == PluginKind::Analyzer;
    check_keys(a,
               analyzer ? std::vector<std::string>{"plugin", "name", "publish", "params"}
                        : std::vector<std::string>{"plugin", "name", "params"},
               at);
    if (!a.contains("plugin") || !a["plugin"].is_string()) {
      throw InputError(at.child("plugin").str() + ": expected a plugin name, got " +
                       json_brief(a.value("plugin", json())));
    }
    PluginSpec spec;
    spec.info = &require_plugin(registry, a["plugin"], kind, at.child("plugin").str());
    require_params_object(a, at);
    if (a.contains("name")) check_analyzer_name(a["name"], at.child("name"));
    spec.name = a.value("name", spec.info->name);
    spec.where = at.str();
    if (!names.insert(spec.name).second) {
      throw InputError(at.child("name").str() +
                       ": expected a name not used by another analyzer or "
                       "writer, got \"" +
                       spec.name + "\" again");
    }
    a["name"] = spec.name;
    if (analyzer) {
      spec.publish = read_publish(a, at);
      a["publish"] = spec.publish;
    }
    specs.push_back(spec);
  }
  return specs;
}

}  // namespace

Pipeline Pipeline::parse(const std::string& text, const std::string& origin,
                         const std::vector<std::string>& sets, const Registry& registry) {
  json root = parse_strict_json(text, origin);
  if (!root.is_object())
    throw InputError(origin + ": expected a JSON object, got " + json_brief(root));
  auto impl = std::make_unique<Impl>();
  impl->origin = origin;
  for (const auto& s : sets) {
    for (Override& o : apply_set(root, s)) impl->overrides.push_back(std::move(o));
  }
  refuse_sets_of_one_value(impl->overrides);
  const JsonLocation top = impl->top();
  check_keys(root,
             {"name", "description", "seed", "source", "analyzers", "writers", "output", "sweep",
              "report"},
             top);

  impl->base_dir = fs::path(origin).parent_path();
  if (root.contains("description") && !root["description"].is_string()) {
    throw InputError(top.child("description").str() + ": expected a string, got " +
                     json_brief(root["description"]));
  }
  impl->name = read_pipeline_name(root, top, origin);
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
  require_params_object(root["source"], src_at);

  const JsonLocation an_at = top.child("analyzers"), wr_at = top.child("writers");
  std::set<std::string> names;
  impl->analyzers =
      parse_plugin_list(root, "analyzers", PluginKind::Analyzer, top, registry, names);
  impl->writers = parse_plugin_list(root, "writers", PluginKind::Writer, top, registry, names);

  const JsonLocation out_at = top.child("output");
  if (!root.contains("output")) root["output"] = json::object();
  json& out = root["output"];
  check_keys(out, {"dir", "save_frames", "frame_stride"}, out_at);
  if (out.contains("dir") && (!out["dir"].is_string() || out["dir"].get<std::string>().empty()))
    throw InputError(out_at.child("dir").str() + ": expected a directory path, got " +
                     json_brief(out["dir"]));
  if (out.contains("save_frames") && !out["save_frames"].is_boolean())
    throw InputError(out_at.child("save_frames").str() + ": expected true or false, got " +
                     json_brief(out["save_frames"]));
  // As plugins' integers are read: 1e3 is 1000, 2^63 is too large (it wrapped below 1).
  std::int64_t stride = 1;
  if (out.contains("frame_stride") && (!as_integer(out["frame_stride"], stride) || stride < 1))
    throw InputError(out_at.child("frame_stride").str() + ": expected an integer >= 1, got " +
                     json_brief(out["frame_stride"]) + why_not_integer(out["frame_stride"]));
  impl->output_dir = out.value("dir", "out/" + impl->name);
  impl->save_frames = out.value("save_frames", true);
  impl->frame_stride = stride;
  out["dir"] = impl->output_dir.string();
  out["save_frames"] = impl->save_frames;
  out["frame_stride"] = impl->frame_stride;

  std::vector<json> assignments{json::object()};
  if (root.contains("sweep")) {
    assignments = expand_sweep(root["sweep"], top.child("sweep"), impl->sweep_paths);
    impl->shared_seeds = shared_sweep_seeds(root["sweep"], top.child("sweep"));
  }
  std::set<std::string> producers{"source"};
  for (const PluginSpec& a : impl->analyzers) producers.insert(a.name);
  check_report_spec(root, top, producers, impl->sweep_paths);
  refuse_sets_the_sweep_replaces(impl->overrides, impl->sweep_paths);
  // A swept value comes from the sweep: from the file, or from the --set that wrote it.
  const JsonLocation swept_at = top.child("sweep").child("parameters");
  std::vector<Override> swept;
  for (const auto& path : impl->sweep_paths)
    swept.push_back({path, swept_at.quoted_key(path).origin()});
  impl->overrides.insert(impl->overrides.end(), swept.begin(), swept.end());
  // Each point starts from the pipeline without its sweep, whose length would make
  // copying it per point quadratic.
  const json sweep = root.contains("sweep") ? root["sweep"] : json();
  root.erase("sweep");

  for (std::size_t k = 0; k < assignments.size(); ++k) {
    PointSpec point;
    point.assignment = assignments[k];
    json p = root;
    for (const auto& [path, value] : assignments[k].items()) {
      const std::string at = top.child("sweep").child("parameters").quoted_key(path).str();
      locate(p, split_path(path, at), at) = value;
    }
    const std::string note = sweep_point_note(point, k);
    try {
      point.source_params = validate_params(p["source"]["params"], impl->source->schema,
                                            src_at.child("params"), impl->base_dir);
      for (std::size_t a = 0; a < impl->analyzers.size(); ++a) {
        point.analyzer_params.push_back(
            validate_params(p["analyzers"][a]["params"], impl->analyzers[a].info->schema,
                            an_at.index(a).child("params"), impl->base_dir));
      }
      for (std::size_t w = 0; w < impl->writers.size(); ++w) {
        point.writer_params.push_back(
            validate_params(p["writers"][w]["params"], impl->writers[w].info->schema,
                            wr_at.index(w).child("params"), impl->base_dir));
      }
    } catch (const InputError& e) {
      throw InputError(e.what() + note);
    }
    point.resolved = p;
    impl->points.push_back(std::move(point));
  }
  impl->resolved = impl->points.front().resolved;
  if (!sweep.is_null()) impl->resolved["sweep"] = sweep;
  return Pipeline(std::move(impl));
}

std::string Pipeline::resolved_json() const { return impl_->resolved.dump(2); }
std::size_t Pipeline::points() const { return impl_->points.size(); }
std::uint64_t Pipeline::seed() const { return impl_->seed; }

}  // namespace granpipe
