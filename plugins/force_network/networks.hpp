#pragma once
// Force networks: the connected components of particles linked by a set of contacts
// (granpipe/connected_components.hpp). A network is a component of two particles or more;
// a particle linked to none is in no network. Labels are 0, 1, ... by size (particles)
// descending, ties by the smallest particle index: label 0 is the largest network,
// whatever order the contacts came in.
#include <vector>

#include "granpipe/connected_components.hpp"
#include "granpipe/frame.hpp"

namespace granpipe::force_network {

using Networks = ConnectedComponents;

// The networks of the frame's particles linked by the contacts in `rows` (rows of its
// contact table naming two particles).
Networks find_networks(const Frame& frame, const std::vector<Eigen::Index>& rows);

}  // namespace granpipe::force_network
