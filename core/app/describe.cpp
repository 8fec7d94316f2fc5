#include <iomanip>
#include <iostream>

#include "commands.hpp"
#include "granpipe/plugin_loader.hpp"

namespace granpipe::app {

void describe(const Registry& registry, const std::string& name) {
  const PluginInfo* info = &require_plugin(registry, name, std::nullopt, "describe");
  std::cout << info->name << " (" << to_string(info->kind) << "): " << info->summary << "\n"
            << "library: " << info->library << "\n\nparameters:\n";
  if (info->schema.specs().empty()) std::cout << "  (none)\n";
  for (const auto& s : info->schema.specs()) {
    std::cout << "  " << s.name << "  " << describe_expected(s);
    if (!s.unit.empty()) std::cout << "  [" << s.unit << "]";
    std::cout << "\n      default: "
              << (s.default_value ? format_value(*s.default_value) : std::string("(required)"))
              << "\n      " << s.doc << "\n";
  }
}

void list_plugins(const Registry& registry) {
  for (PluginKind kind : {PluginKind::Source, PluginKind::Analyzer, PluginKind::Writer}) {
    std::cout << to_string(kind) << "s:\n";
    for (const auto& p : registry.plugins()) {
      if (p.kind != kind) continue;
      std::cout << "  " << std::left << std::setw(16) << p.name << " " << p.summary << "\n";
    }
  }
  const LoadReport& report = load_report(registry);
  if (!report.refused.empty()) {
    std::cout << "refused libraries:\n";
    for (const auto& r : report.refused) std::cout << "  " << r.library << " " << r.reason << "\n";
  }
  if (!report.shadowed.empty()) {
    std::cout << "ignored (a library earlier on the search path provides the name):\n";
    for (const auto& s : report.shadowed) {
      std::cout << "  " << s.name << " of " << s.ignored << " (used: " << s.used << ")\n";
    }
  }
  std::cout << "search path (GRANPIPE_PLUGIN_PATH, then the plugins beside granpipe):";
  for (const auto& d : report.searched) std::cout << " " << d.string();
  std::cout << "\n";
}

}  // namespace granpipe::app
