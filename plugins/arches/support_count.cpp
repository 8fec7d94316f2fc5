#include "support_count.hpp"

#include "mutual_stability.hpp"

namespace granpipe::arches {

SupportCount count_supports(const Supports& s) {
  SupportCount c;
  c.disks = s.left.size();
  const std::int64_t base = partner::wall(Wall::YLow);
  for (Eigen::Index i = 0; i < c.disks; ++i) {
    const std::int64_t l = s.left(i), r = s.right(i);
    // A disk on the base carries the base on both sides: one partner, one contact.
    const Eigen::Index k =
        (l != partner::none) + (r != partner::none) - (l == r && l != partner::none);
    c.supports += k;
    c.base_disks += (l == base || r == base);
    c.mutual_pairs += (right_mutual_partner(s, i) != partner::none);
  }
  return c;
}

}  // namespace granpipe::arches
