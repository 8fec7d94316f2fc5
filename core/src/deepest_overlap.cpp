#include "granpipe/deepest_overlap.hpp"

#include <algorithm>

#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

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

void declare_max_overlap(Schema& schema, double default_value, const std::string& what) {
  schema
      .real(
          "max_overlap", default_value,
          "deepest overlap of two particles accepted, as a fraction of the smaller radius: " + what)
      .range(0.0, 1.0);
}

void refuse_deep_overlap(const Frame& frame, double max_overlap, const std::string& param,
                         const std::string& why, const std::string& where) {
  const auto deepest = deepest_pair_overlap(frame, where);
  if (!deepest || deepest->fraction <= max_overlap) return;
  throw InputError(where + ": particles " + std::to_string(frame.id()[deepest->i]) + " and " +
                   std::to_string(frame.id()[deepest->j]) + " overlap by " +
                   format_number(deepest->fraction) + " of the smaller radius, expected at most " +
                   format_number(max_overlap) + " (" + param + ")" + why);
}

}  // namespace granpipe
