#pragma once
// Seeded random streams. One seed in the pipeline gives every consumer (a plugin, a
// sweep point, a thread) its own independent stream, derived from the seed and a
// name, so results do not depend on who asked first or how many threads ran.
#include <cmath>
#include <cstdint>
#include <random>
#include <string_view>
#include <utility>
#include <vector>

#include "granpipe/xoshiro.hpp"

namespace granpipe {

// The draws below are written once over any 64-bit engine. RandomStream's Mersenne
// Twister is what every result so far was made with (changing it would change them all);
// FastRandomStream's xoshiro256++ is for hot Monte Carlo loops, where the Twister's
// 2.5 KB state and its refill were a tenth of a trial move's time.
template <class Engine>
class BasicRandomStream {
 public:
  explicit BasicRandomStream(std::uint64_t seed) : engine_(seed) {}
  std::uint64_t bits() { return engine_(); }
  // Uniform in [0, 1), 53 random bits: the same on every platform (unlike std distributions).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // Uniform integer in [0, n), n > 0 (Lemire's multiply-and-reject: exactly uniform, and
  // no division except in the rare rejection check).
  std::uint64_t below(std::uint64_t n) {
    unsigned __int128 m = static_cast<unsigned __int128>(engine_()) * n;
    if (static_cast<std::uint64_t>(m) < n) {
      const std::uint64_t threshold = (0 - n) % n;
      while (static_cast<std::uint64_t>(m) < threshold)
        m = static_cast<unsigned __int128>(engine_()) * n;
    }
    return static_cast<std::uint64_t>(m >> 64);
  }
  // Fisher-Yates shuffle of fewer than 2^32 items. Each 64-bit draw gives two 32-bit
  // ones: shuffles sit in hot loops (the move order of a deposition sweep).
  template <class T>
  void shuffle(std::vector<T>& v);
  // Standard normal (Marsaglia polar method, platform independent).
  double normal();

 private:
  Engine engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

template <class Engine>
template <class T>
void BasicRandomStream<Engine>::shuffle(std::vector<T>& v) {
  std::uint64_t bits = 0;
  int unused = 0;
  auto draw32 = [&]() -> std::uint32_t {
    if (unused == 0) {
      bits = engine_();
      unused = 2;
    }
    return static_cast<std::uint32_t>(bits >> (32 * --unused));
  };
  for (std::size_t n = v.size(); n > 1; --n) {
    const auto n32 = static_cast<std::uint32_t>(n);
    std::uint64_t m = static_cast<std::uint64_t>(draw32()) * n32;
    if (static_cast<std::uint32_t>(m) < n32) {
      const std::uint32_t threshold = (0u - n32) % n32;
      while (static_cast<std::uint32_t>(m) < threshold)
        m = static_cast<std::uint64_t>(draw32()) * n32;
    }
    std::swap(v[n - 1], v[static_cast<std::size_t>(m >> 32)]);
  }
}

template <class Engine>
double BasicRandomStream<Engine>::normal() {
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

using RandomStream = BasicRandomStream<std::mt19937_64>;
using FastRandomStream = BasicRandomStream<Xoshiro256pp>;

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
