#include "granpipe/random.hpp"

#include <cmath>

namespace granpipe {
namespace {
// SplitMix64 finaliser: a bijective mix, so distinct inputs give distinct seeds.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
// FNV-1a: stable across platforms and runs, unlike std::hash.
std::uint64_t hash_name(std::string_view s) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
  return h;
}
}  // namespace

double RandomStream::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u, v, s;
  do {
    u = uniform(-1.0, 1.0);
    v = uniform(-1.0, 1.0);
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double f = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * f;
  has_spare_ = true;
  return u * f;
}

Seeds Seeds::derive(std::string_view name, std::uint64_t index) const {
  return Seeds(mix(mix(seed_ ^ hash_name(name)) + index));
}

RandomStream Seeds::stream(std::string_view name, std::uint64_t index) const {
  return RandomStream(derive(name, index).seed());
}

}  // namespace granpipe
