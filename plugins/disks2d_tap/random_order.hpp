#pragma once
// Random choices of the deposition's move order, drawn from a granpipe RandomStream so
// they are reproducible on every platform (std:: distributions are not).
#include <cstdint>
#include <utility>
#include <vector>

#include "granpipe/random.hpp"

namespace granpipe::disks2d_tap {

// Uniform integer in [0, n) (Lemire's multiply-and-reject method: unbiased, and unlike
// a modulo it needs no division except in the rare rejection check).
inline std::uint64_t uniform_below(RandomStream& rng, std::uint64_t n) {
  unsigned __int128 m = static_cast<unsigned __int128>(rng.bits()) * n;
  auto low = static_cast<std::uint64_t>(m);
  if (low < n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (low < threshold) {
      m = static_cast<unsigned __int128>(rng.bits()) * n;
      low = static_cast<std::uint64_t>(m);
    }
  }
  return static_cast<std::uint64_t>(m >> 64);
}

// Fisher-Yates shuffle. Each 64-bit random number gives two 32-bit draws, each mapped
// to [0, n) by the same multiply-and-reject method: the shuffle is a good part of a
// sweep's cost.
inline void shuffle(std::vector<std::int32_t>& v, RandomStream& rng) {
  std::uint64_t bits = 0;
  int unused = 0;
  auto draw32 = [&]() -> std::uint32_t {
    if (unused == 0) {
      bits = rng.bits();
      unused = 2;
    }
    return static_cast<std::uint32_t>(bits >> (32 * --unused));
  };
  for (std::size_t n = v.size(); n > 1; --n) {
    const auto n32 = static_cast<std::uint32_t>(n);
    std::uint64_t m = static_cast<std::uint64_t>(draw32()) * n32;
    if (static_cast<std::uint32_t>(m) < n32) {
      const std::uint32_t threshold = (0u - n32) % n32;
      while (static_cast<std::uint32_t>(m) < threshold) {
        m = static_cast<std::uint64_t>(draw32()) * n32;
      }
    }
    std::swap(v[n - 1], v[static_cast<std::size_t>(m >> 32)]);
  }
}

}  // namespace granpipe::disks2d_tap
