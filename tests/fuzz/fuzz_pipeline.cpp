// libFuzzer target: a pipeline's JSON text and its --set values, parsed and validated
// against the schemas of the real plugins (those the granpipe executable would load).
// Input: the JSON text, then up to four --set strings, each after a NUL byte.
// Anything but an InputError escaping is a finding (docs/fuzzing.md).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/pipeline.hpp"
#include "granpipe/plugin_loader.hpp"

namespace {

constexpr std::size_t kMaxSets = 4;

const granpipe::Registry& plugins() {
  static const granpipe::Registry* registry = [] {
    auto* r = new granpipe::Registry;  // kept for the process: plugins stay loaded
    granpipe::load_plugins(*r, granpipe::plugin_search_path());
    return r;
  }();
  return *registry;
}

// The text up to the first NUL, and the --set strings between the following ones.
std::vector<std::string> split_at_nul(const std::string& input) {
  std::vector<std::string> parts{""};
  for (const char c : input) {
    if (c != '\0') {
      parts.back() += c;
    } else if (parts.size() <= kMaxSets) {
      parts.emplace_back();
    } else {
      break;
    }
  }
  return parts;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string> parts =
      split_at_nul(std::string(reinterpret_cast<const char*>(data), size));
  const std::vector<std::string> sets(parts.begin() + 1, parts.end());
  try {
    const granpipe::Pipeline p = granpipe::Pipeline::parse(parts[0], "fuzz.json", sets, plugins());
    static_cast<void>(p.resolved_json());
    static_cast<void>(p.points());
  } catch (const granpipe::InputError&) {
    // Bad input, reported as it should be.
  }
  return 0;
}
