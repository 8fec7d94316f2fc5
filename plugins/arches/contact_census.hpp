#pragma once
// Geometric contacts of a 2D frame (disk-disk, disk-wall, disk-base) sorted into
// supporting contacts (a support label of either disk names the partner) and
// non-supporting ones.
#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/frame.hpp"
#include "mutual_stability.hpp"

namespace granpipe::arches {

struct ContactCensus {
  Eigen::Index contacts = 0;    // all geometric contacts
  Eigen::Index supporting = 0;  // of which a support label names the partner

  Eigen::Index non_supporting() const { return contacts - supporting; }
};

// `contacts` are the frame's contacts by distance (core's find_contacts_by_distance).
ContactCensus census_contacts(const Supports& supports, const DistanceContacts& contacts);

}  // namespace granpipe::arches
