#include "granpipe/random.hpp"

namespace granpipe {
namespace {
// SplitMix64's output of one step from z: distinct inputs give distinct seeds.
std::uint64_t mix(std::uint64_t z) { return splitmix64(z); }
// FNV-1a: stable across platforms and runs, unlike std::hash.
std::uint64_t hash_name(std::string_view s) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
  return h;
}
}  // namespace

Seeds Seeds::derive(std::string_view name, std::uint64_t index) const {
  return Seeds(mix(mix(seed_ ^ hash_name(name)) + index));
}

RandomStream Seeds::stream(std::string_view name, std::uint64_t index) const {
  return RandomStream(derive(name, index).seed());
}

}  // namespace granpipe
