#pragma once
// The strong sub-network (the paper's Fig. 11 and Sec. III.B): the force-network contacts
// with |F_n| > <F_n>, the particles they touch, and its largest connected component.
#include "force_contacts.hpp"
#include "networks.hpp"

namespace granpipe::force_network {

struct StrongNetwork {
  IntArray flag;                  // per contact row: 1 for a strong contact, else 0
  long contacts = 0;              // strong contacts
  long particles = 0;             // particles touched by a strong contact
  long particles_in_largest = 0;  // of those, the ones in the largest force network
  ComponentSize largest;          // the largest connected component of strong contacts
};

StrongNetwork strong_network(const Frame& frame, const ForceContacts& forces,
                             const Networks& networks);

}  // namespace granpipe::force_network
