#include "granpipe/plugin_loader.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <sstream>
#include <utility>

#include "did_you_mean.hpp"

namespace granpipe {
namespace fs = std::filesystem;

fs::path executable_dir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

namespace {
constexpr const char* kPrefix = "granpipe_";
constexpr const char* kEntrySymbol = "granpipe_plugin";

// The plugin name a library file promises, from its name granpipe_<name>.so.
std::string promised_name(const fs::path& lib) {
  std::string stem = lib.stem().string();
  return stem.rfind(kPrefix, 0) == 0 ? stem.substr(std::char_traits<char>::length(kPrefix)) : stem;
}

// Releases of one minor version keep the plugin ABI; a plugin of another minor version is
// refused even when someone forgot to bump GRANPIPE_ABI_VERSION.
bool same_minor_version(const char* plugin_version) {
  if (!plugin_version) return false;
  const std::string ours = GRANPIPE_VERSION, theirs = plugin_version;
  const auto minor_end = [](const std::string& v) { return v.find('.', v.find('.') + 1); };
  return ours.substr(0, minor_end(ours)) == theirs.substr(0, minor_end(theirs));
}

void load_library(Registry& registry, LoadReport& report, const fs::path& file) {
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* err = dlerror();
    report.refused.push_back(
        {file.string(), std::string("cannot be loaded: ") + (err ? err : "unknown error")});
    return;
  }
  auto* entry = static_cast<const granpipe_plugin_entry*>(dlsym(handle, kEntrySymbol));
  if (!entry) {
    report.refused.push_back(
        {file.string(), "is not a granpipe plugin (no granpipe_plugin entry point)"});
    dlclose(handle);
    return;
  }
  // Before ABI 2 the descriptor had another layout: only its first field can be read.
  const bool readable = entry->abi_version >= 2;
  if (entry->abi_version != GRANPIPE_ABI_VERSION || !same_minor_version(entry->core_version)) {
    std::ostringstream why;
    why << "was built against granpipe "
        << (readable && entry->core_version ? entry->core_version : "of another version")
        << " (plugin ABI " << (entry->abi_version & 0xffffffffu) << "), but this is granpipe "
        << GRANPIPE_VERSION << " (plugin ABI " << GRANPIPE_ABI_VERSION
        << "): rebuild the plugin against this version";
    report.refused.push_back({file.string(), why.str()});
    dlclose(handle);
    return;
  }
  if (entry->layout_fingerprint != kLayoutFingerprint) {
    std::ostringstream why;
    why << "was built against granpipe headers whose public types have another memory layout "
        << "(layout fingerprint " << std::hex << entry->layout_fingerprint << ", this granpipe "
        << kLayoutFingerprint << "): rebuild the plugin against this version";
    report.refused.push_back({file.string(), why.str()});
    dlclose(handle);
    return;
  }
  // Plugins stay loaded for the life of the process: their code backs the registry.
  Registry found;
  try {
    entry->register_plugins(found);
  } catch (const std::exception& e) {
    report.refused.push_back({file.string(), std::string("failed to register: ") + e.what()});
    return;
  }
  for (PluginInfo info : found.plugins()) {
    info.library = file.string();
    if (const PluginInfo* earlier = registry.find(info.name)) {
      report.shadowed.push_back({info.name, earlier->library, file.string()});
    } else {
      registry.add(std::move(info));
    }
  }
}
}  // namespace

std::vector<fs::path> plugin_search_path() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("GRANPIPE_PLUGIN_PATH")) {
    std::stringstream ss(env);
    std::string item;
    while (std::getline(ss, item, ':'))
      if (!item.empty()) dirs.emplace_back(item);
  }
  const fs::path exe = executable_dir();
  if (!exe.empty()) dirs.push_back((exe / GRANPIPE_PLUGIN_RELDIR).lexically_normal());
  return dirs;
}

std::vector<std::string> LoadReport::warnings() const {
  std::vector<std::string> lines;
  for (const fs::path& d : without_plugins) {
    lines.push_back("plugin directory " + d.string() + " holds no granpipe_*.so plugin library");
  }
  // Copies of a whole plugin directory earlier on the path: one line, not one per plugin.
  std::map<std::pair<fs::path, fs::path>, std::vector<const Shadowed*>> by_directories;
  for (const Shadowed& s : shadowed) {
    by_directories[{fs::path(s.ignored).parent_path(), fs::path(s.used).parent_path()}].push_back(
        &s);
  }
  for (const auto& [dirs, group] : by_directories) {
    if (group.size() == 1) {
      const Shadowed& s = *group.front();
      lines.push_back("plugin \"" + s.name + "\" of " + s.ignored + " ignored: " + s.used +
                      ", earlier on the search path, provides it");
      continue;
    }
    std::string names;
    for (const Shadowed* s : group) names += (names.empty() ? "" : ", ") + s->name;
    lines.push_back(std::to_string(group.size()) + " plugins of " + dirs.first.string() +
                    " ignored (" + names + "): the libraries of " + dirs.second.string() +
                    ", earlier on the search path, provide them");
  }
  return lines;
}

void load_plugins(Registry& registry, const std::vector<fs::path>& dirs) {
  auto report = std::make_shared<LoadReport>();
  std::vector<fs::path> seen;
  for (const auto& dir : dirs) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(dir, ec);
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) continue;
    seen.push_back(canonical);
    report->searched.push_back(dir);
    std::vector<fs::path> libs;
    if (fs::is_directory(dir, ec)) {
      for (const auto& e : fs::directory_iterator(dir, ec)) {
        const fs::path& p = e.path();
        if (p.extension() == ".so" && p.filename().string().rfind(kPrefix, 0) == 0)
          libs.push_back(p);
      }
    }
    if (libs.empty()) report->without_plugins.push_back(dir);
    std::sort(libs.begin(), libs.end());  // a stable order: same search path, same plugins
    for (const auto& lib : libs) load_library(registry, *report, lib);
  }
  registry.report_ = std::move(report);
}

const LoadReport& load_report(const Registry& registry) {
  static const LoadReport none;
  return registry.report_ ? *registry.report_ : none;
}

namespace {
const char* article(PluginKind k) { return k == PluginKind::Analyzer ? "an" : "a"; }
}  // namespace

const PluginInfo& require_plugin(const Registry& registry, const std::string& name,
                                 std::optional<PluginKind> kind, const std::string& where) {
  const std::string wanted =
      kind ? std::string(article(*kind)) + " " + to_string(*kind) + " plugin" : "a plugin";
  if (const PluginInfo* p = registry.find(name)) {
    if (kind && p->kind != *kind) {
      throw InputError(where + ": expected " + wanted + ", got \"" + name + "\", which is " +
                       article(p->kind) + " " + to_string(p->kind));
    }
    return *p;
  }
  const LoadReport& report = load_report(registry);
  for (const auto& r : report.refused) {
    if (promised_name(r.library) == name) {
      throw InputError(where + ": plugin \"" + name + "\" refused: " + r.library + " " + r.reason);
    }
  }
  std::vector<std::string> names;
  for (const auto& p : registry.plugins())
    if (!kind || p.kind == *kind) names.push_back(p.name);
  std::string searched;
  for (const fs::path& d : report.searched) searched += (searched.empty() ? "" : ", ") + d.string();
  const std::string where_searched =
      report.searched.empty()
          ? ""
          : "; searched " + searched + " (GRANPIPE_PLUGIN_PATH, then the plugins beside granpipe)";
  throw InputError(where + ": expected " + wanted + ", got unknown \"" + name + "\"" +
                   did_you_mean(name, names) +
                   known_list(names, "none (is GRANPIPE_PLUGIN_PATH right?)") + where_searched);
}

}  // namespace granpipe
