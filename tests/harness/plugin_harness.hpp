#pragma once
// What a pipeline gives a plugin, for plugin tests: the parameters validated through the
// plugin's schema exactly as a pipeline validates them (defaults filled in, a bad value
// refused with the pipeline's message), its seeds, one thread, a quiet log and no progress
// bar. Tests then make the plugin from the context, or have the harness make it.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/plugin.hpp"

namespace granpipe::test {

class PluginHarness {
 public:
  // `params` as a pipeline file gives them, e.g. {{"cells", {3, 3, 3}}}; an InputError as
  // the pipeline would report it ("test: params.cells: expected ...").
  // `name` is the instance's name (the files it writes start with it).
  PluginHarness(const Schema& schema, nlohmann::json params, std::uint64_t seed,
                std::filesystem::path output_dir, std::string name);
  PluginHarness(const PluginHarness&) = delete;
  PluginHarness& operator=(const PluginHarness&) = delete;

  const PluginContext& context() const { return *context_; }
  operator const PluginContext&() const {
    return *context_;
  }  // NOLINT: a context is what it is for
  const Params& params() const { return params_; }
  Log& log() { return log_; }
  // Sends the log to a file of the test program's own, as a run sends it to run.log;
  // logged_lines() ends it and gives its lines (the file removed).
  void keep_log();
  std::vector<std::string> logged_lines();

 private:
  Log log_;
  std::filesystem::path log_file_;
  Progress progress_;
  Params params_;
  std::unique_ptr<PluginContext> context_;
};

// The context of a plugin with this schema.
std::unique_ptr<PluginHarness> make_context(const Schema& schema, nlohmann::json params = {},
                                            std::uint64_t seed = 1,
                                            std::filesystem::path output_dir = {});
// The context of the installed plugin `plugin`, named after it (found on GRANPIPE_PLUGIN_PATH by
// the real loader, whose registry stays loaded for the test program).
std::unique_ptr<PluginHarness> make_context(const std::string& plugin, nlohmann::json params = {},
                                            std::uint64_t seed = 1,
                                            std::filesystem::path output_dir = {});
// The message of the InputError `refused` throws, to compare whole; "no refusal" when it
// throws none (the comparison then fails showing that the input was accepted).
template <class F>
std::string input_error_of(F&& refused) {
  try {
    refused();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no refusal";
}

// A warning said for the first such frame only: the log `lines` start with `first`, and no
// later line says `marker` again.
inline void expect_said_once(const std::vector<std::string>& lines, const std::string& first,
                             const std::string& marker) {
  ASSERT_GE(lines.size(), 1u);
  EXPECT_EQ(lines[0], first);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    EXPECT_EQ(lines[k].find(marker), std::string::npos) << lines[k];
  }
}

// The installed plugins, loaded once.
const Registry& installed_plugins();

}  // namespace granpipe::test
