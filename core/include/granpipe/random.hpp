#pragma once
// Seeded random streams. One seed in the pipeline gives every consumer (a plugin, a
// sweep point, a thread) its own independent stream, derived from the seed and a
// name, so results do not depend on who asked first or how many threads ran.
#include <cstdint>
#include <random>
#include <string_view>

namespace granpipe {

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}
  std::uint64_t bits() { return engine_(); }
  // Uniform in [0, 1), 53 random bits: the same on every platform (unlike std distributions).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n);
  // Standard normal (Marsaglia polar method, platform independent).
  double normal();
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

class Seeds {
 public:
  explicit Seeds(std::uint64_t seed) : seed_(seed) {}
  std::uint64_t seed() const { return seed_; }
  // A child seed for a named purpose and index, e.g. derive("point", 3).
  Seeds derive(std::string_view name, std::uint64_t index = 0) const;
  RandomStream stream(std::string_view name, std::uint64_t index = 0) const;

 private:
  std::uint64_t seed_;
};

}  // namespace granpipe
