#include "granpipe/plugin.hpp"

namespace granpipe {

const char* to_string(PluginKind k) { return k == PluginKind::Source ? "source" : "analyzer"; }

void Registry::add(PluginInfo info) {
  if (find(info.name)) {
    throw InternalError("plugin \"" + info.name + "\" registered twice in one registry");
  }
  if (info.kind == PluginKind::Source ? !info.make_source : !info.make_analyzer) {
    throw InternalError("plugin '" + info.name + "' registered without a factory");
  }
  plugins_.push_back(std::move(info));
}

const PluginInfo* Registry::find(const std::string& name) const {
  for (const auto& p : plugins_)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace granpipe
