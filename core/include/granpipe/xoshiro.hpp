#pragma once
// xoshiro256++ (Blackman and Vigna, 2019): 256 bits of state, period 2^256 - 1, a few
// cycles per draw, and it passes BigCrush. A standard UniformRandomBitGenerator, so it
// can drive BasicRandomStream like std::mt19937_64 does.
#include <array>
#include <cstdint>
#include <limits>

namespace granpipe {

// SplitMix64 (Steele, Lea and Flood): advances `state` by the golden-ratio increment and
// returns it through a bijective mix, so distinct states give distinct outputs.
inline std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class Xoshiro256pp {
 public:
  using result_type = std::uint64_t;
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }

  // The state from a 64-bit seed by SplitMix64, as the authors advise: never all zero,
  // and nearby seeds give unrelated states.
  explicit Xoshiro256pp(std::uint64_t seed) {
    for (auto& word : s_) word = splitmix64(seed);
  }
  // A given state (not all zero), for checks against the authors' reference outputs.
  explicit Xoshiro256pp(const std::array<std::uint64_t, 4>& state) : s_(state) {}

  result_type operator()() {
    const std::uint64_t result = rotl(s_[0] + s_[3], 23) + s_[0];
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::array<std::uint64_t, 4> s_;
};

}  // namespace granpipe
