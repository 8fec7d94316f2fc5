#include "granpipe/plugin.hpp"

namespace granpipe {

const char* to_string(PluginKind k) {
  switch (k) {
    case PluginKind::Source:
      return "source";
    case PluginKind::Analyzer:
      return "analyzer";
    case PluginKind::Writer:
      return "writer";
  }
  return "?";
}

void Registry::add(PluginInfo info) {
  if (find(info.name)) {
    throw InternalError("plugin \"" + info.name + "\" registered twice in one registry");
  }
  const bool made = info.kind == PluginKind::Source     ? bool(info.make_source)
                    : info.kind == PluginKind::Analyzer ? bool(info.make_analyzer)
                                                        : bool(info.make_writer);
  if (!made) {
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
