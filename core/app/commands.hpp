#pragma once
#include <string>

#include "granpipe/plugin.hpp"

namespace granpipe::app {

// `granpipe describe NAME`: the plugin's schema as documentation.
void describe(const Registry& registry, const std::string& name);
// `granpipe plugins`: every plugin found, and every library refused.
void list_plugins(const Registry& registry);
// `granpipe inspect FILE.h5`: frames, N, dim and what each frame holds.
void inspect(const std::string& path, long max_rows);

}  // namespace granpipe::app
