#pragma once
#include <filesystem>
#include <optional>
#include <vector>

#include "granpipe/plugin.hpp"

namespace granpipe {

// Directories searched for plugin libraries, in order: GRANPIPE_PLUGIN_PATH (colon
// separated), then the plugin directory of the executable's own prefix (build or install).
std::vector<std::filesystem::path> plugin_search_path();

// Loads every granpipe_*.so in `dirs` into `registry`. A library built against another
// ABI is refused (recorded in registry.refused()) without calling into it. When two
// libraries provide the same plugin name the first found wins, so a user's directory on
// GRANPIPE_PLUGIN_PATH can override an installed plugin.
void load_plugins(Registry& registry, const std::vector<std::filesystem::path>& dirs);

// The plugin `name` (of `kind`, when given), or an InputError naming `where` with a
// did-you-mean, or the refusal of a library that would have provided it.
const PluginInfo& require_plugin(const Registry& registry, const std::string& name,
                                 std::optional<PluginKind> kind, const std::string& where);

}  // namespace granpipe
