#include <iomanip>
#include <iostream>
#include <string>

#include "commands.hpp"
#include "granpipe/plugin_loader.hpp"

namespace granpipe::app {

namespace {

void print_params(const Schema& schema, const std::string& indent);

std::string default_text(const ParamSpec& s) {
  if (s.default_value) return format_value(*s.default_value);
  return s.default_json.value_or("(required)");
}

// The parameter's line, its default and doc indented below, then the keys of its objects.
void print_param(const ParamSpec& s, const std::string& indent) {
  std::cout << indent << s.name << "  " << describe_expected(s);
  if (!s.unit.empty()) std::cout << "  [" << s.unit << "]";
  const std::string inner = indent + "    ";
  std::cout << "\n";
  if (s.type != ParamType::Object) std::cout << inner << "default: " << default_text(s) << "\n";
  if (s.applies) std::cout << inner << "acts only with " << s.applies_where << "\n";
  std::cout << inner << s.doc << "\n";
  if (s.type == ParamType::Species) std::cout << inner << "each species:\n";
  if (s.type == ParamType::Pairs) std::cout << inner << "each pair (its keys override \"*\"'s):\n";
  if (s.fields) print_params(*s.fields, s.type == ParamType::Object ? inner : inner + "  ");
}

void print_params(const Schema& schema, const std::string& indent) {
  for (const auto& s : schema.specs()) print_param(s, indent);
}

}  // namespace

void describe(const Registry& registry, const std::string& name) {
  const PluginInfo* info = &require_plugin(registry, name, std::nullopt, "describe");
  std::cout << info->name << " (" << to_string(info->kind) << "): " << info->summary << "\n"
            << "library: " << info->library << "\n\nparameters:\n";
  if (info->schema.specs().empty()) std::cout << "  (none)\n";
  print_params(info->schema, "  ");
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
