#include "granpipe/plugin.hpp"

namespace granpipe {

const char* to_string(PluginKind k) { return k == PluginKind::Source ? "source" : "analyzer"; }

void Registry::add(PluginInfo info) {
  if (find(info.name)) return;  // the first library on the search path wins
  if (info.kind == PluginKind::Source ? !info.make_source : !info.make_analyzer) {
    throw InternalError("plugin '" + info.name + "' registered without a factory");
  }
  info.library = current_library_;
  plugins_.push_back(std::move(info));
}

const PluginInfo* Registry::find(const std::string& name) const {
  for (const auto& p : plugins_)
    if (p.name == name) return &p;
  return nullptr;
}

void Registry::refuse(std::string library, std::string reason) {
  refused_.push_back({std::move(library), std::move(reason)});
}

}  // namespace granpipe
