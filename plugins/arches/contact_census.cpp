#include "contact_census.hpp"

namespace granpipe::arches {

namespace {

bool names(const Supports& s, std::int64_t i, std::int64_t p) {
  return s.left(i) == p || s.right(i) == p;
}

}  // namespace

ContactCensus census_contacts(const Supports& supports, const DistanceContacts& contacts) {
  ContactCensus census;
  census.contacts = contacts.size();
  for (Eigen::Index k = 0; k < contacts.size(); ++k) {
    const std::int64_t i = contacts.i(k), j = contacts.j(k);
    // A wall partner can only be named by disk i; a disk pair by either disk.
    census.supporting +=
        names(supports, i, j) || (partner::is_particle(j) && names(supports, j, i));
  }
  return census;
}

}  // namespace granpipe::arches
