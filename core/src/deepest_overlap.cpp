#include "granpipe/deepest_overlap.hpp"

#include <algorithm>

#include "granpipe/contacts_by_distance.hpp"

namespace granpipe {

std::optional<PairOverlap> deepest_pair_overlap(const Frame& frame, const std::string& where) {
  if (frame.size() < 2) return std::nullopt;
  // Pairs at zero tolerance are exactly the touching and overlapping ones.
  const DistanceContacts touching = find_contacts_by_distance(frame, 0.0, where);
  std::optional<PairOverlap> deepest;
  for (Eigen::Index k = 0; k < touching.pairs; ++k) {
    const auto i = touching.i[k], j = touching.j[k];
    const double fraction = -touching.gap[k] / std::min(frame.radius()[i], frame.radius()[j]);
    if (fraction > 0.0 && (!deepest || fraction > deepest->fraction)) deepest = {i, j, fraction};
  }
  return deepest;
}

}  // namespace granpipe
