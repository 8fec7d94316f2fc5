#pragma once
// The order in which one Monte Carlo loop of a tap visits the disks. In index order the
// same disks jump first in every loop and every tap, a fixed priority the paper does not
// state; shuffled, every loop draws a fresh permutation.
#include <cstdint>
#include <numeric>
#include <vector>

#include "granpipe/params.hpp"
#include "granpipe/random.hpp"

namespace granpipe::disks2d_tap {

enum class McOrder : std::uint8_t { Index, Shuffled };
inline ChoiceNames<McOrder> choice_names(McOrder) {
  return {{"index", McOrder::Index}, {"shuffled", McOrder::Shuffled}};
}

class VisitOrder {
 public:
  explicit VisitOrder(McOrder order) : order_(order) {}

  // Disks 0..n-1, in index order. The buffer only grows, so taps of one bed allocate once.
  void reset(std::size_t n) {
    disks_.resize(n);
    std::iota(disks_.begin(), disks_.end(), std::int32_t{0});
  }
  // The disks in the order of the next loop. Index order draws nothing from `rng`;
  // shuffled, a Fisher-Yates pass over the previous order gives a uniform permutation
  // whatever that order was.
  const std::vector<std::int32_t>& next(RandomStream& rng) {
    if (order_ == McOrder::Shuffled) rng.shuffle(disks_);
    return disks_;
  }

 private:
  McOrder order_;
  std::vector<std::int32_t> disks_;
};

}  // namespace granpipe::disks2d_tap
