#pragma once
#include <filesystem>
#include <optional>
#include <vector>

#include "granpipe/plugin.hpp"

namespace granpipe {

// Directories searched for plugin libraries, in order: GRANPIPE_PLUGIN_PATH (colon
// separated), then the plugin directory of the executable's own prefix (build or install).
std::vector<std::filesystem::path> plugin_search_path();

// The directory of the running executable (empty if unknown): the build and install trees
// place the plugins and the report script relative to it.
std::filesystem::path executable_dir();

// What the loader saw, for the messages of `granpipe plugins` and of a plugin not found.
struct LoadReport {
  std::vector<std::filesystem::path> searched;  // the directories, in order
  // Directories that do not exist or hold no granpipe_*.so library.
  std::vector<std::filesystem::path> without_plugins;
  struct Refusal {
    std::string library, reason;
  };
  std::vector<Refusal> refused;  // wrong ABI or layout, no entry point, not loadable
  struct Shadowed {
    std::string name, used, ignored;  // plugin name, the library kept, the one ignored
  };
  std::vector<Shadowed> shadowed;
  // For stderr: one line per empty directory, and one per directory whose plugins a
  // directory earlier on the path shadows (naming them).
  std::vector<std::string> warnings() const;
};

// Loads every granpipe_*.so in `dirs` into `registry`. A library built against another
// ABI or layout is refused without calling into it. When two libraries provide the same
// plugin name the first found wins (so a user's directory on GRANPIPE_PLUGIN_PATH can
// override an installed plugin) and the other is reported as shadowed.
void load_plugins(Registry& registry, const std::vector<std::filesystem::path>& dirs);
// The report of the last load into `registry` (empty when none).
const LoadReport& load_report(const Registry& registry);

// The plugin `name` (of `kind`, when given), or an InputError naming `where` with a
// did-you-mean, or the refusal of a library that would have provided it.
const PluginInfo& require_plugin(const Registry& registry, const std::string& name,
                                 std::optional<PluginKind> kind, const std::string& where);

}  // namespace granpipe
