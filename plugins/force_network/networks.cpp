#include "networks.hpp"

namespace granpipe::force_network {

Networks find_networks(const Frame& frame, const std::vector<Eigen::Index>& rows) {
  std::vector<ParticlePair> edges;
  edges.reserve(rows.size());
  for (Eigen::Index row : rows) edges.emplace_back(frame.contact_i()[row], frame.contact_j()[row]);
  return connected_components(frame.size(), edges);
}

}  // namespace granpipe::force_network
