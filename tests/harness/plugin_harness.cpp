#include "plugin_harness.hpp"

#include <unistd.h>

#include <fstream>
#include <string>

#include "granpipe/plugin_loader.hpp"
#include "param_validation.hpp"

namespace granpipe::test {

PluginHarness::PluginHarness(const Schema& schema, nlohmann::json params, std::uint64_t seed,
                             std::filesystem::path output_dir, std::string name) {
  log_.set_quiet(true);
  progress_.set_enabled(false);
  params_ = validate_params(params, schema, JsonLocation{"test", "params"},
                            std::filesystem::current_path());
  context_ = std::make_unique<PluginContext>(PluginContext{
      params_, Seeds(seed), 1, log_, progress_, std::move(output_dir), std::move(name), "params"});
}

void PluginHarness::keep_log() {
  log_file_ = std::filesystem::temp_directory_path() /
              ("granpipe_test_" + std::to_string(getpid()) + "_" + context_->name + ".log");
  std::filesystem::remove(log_file_);
  log_.open_file(log_file_.string());
}

std::vector<std::string> PluginHarness::logged_lines() {
  log_.close_file();
  std::vector<std::string> lines;
  std::ifstream in(log_file_);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::filesystem::remove(log_file_);
  return lines;
}

std::unique_ptr<PluginHarness> make_context(const Schema& schema, nlohmann::json params,
                                            std::uint64_t seed, std::filesystem::path output_dir) {
  return std::make_unique<PluginHarness>(schema, std::move(params), seed, std::move(output_dir),
                                         "test");
}

const Registry& installed_plugins() {
  static const Registry registry = [] {
    Registry r;
    load_plugins(r, plugin_search_path());
    return r;
  }();
  return registry;
}

std::unique_ptr<PluginHarness> make_context(const std::string& plugin, nlohmann::json params,
                                            std::uint64_t seed, std::filesystem::path output_dir) {
  const PluginInfo& info = require_plugin(installed_plugins(), plugin, std::nullopt, "test");
  return std::make_unique<PluginHarness>(info.schema, std::move(params), seed,
                                         std::move(output_dir), plugin);
}

}  // namespace granpipe::test
