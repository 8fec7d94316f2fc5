#include "strong_network.hpp"

namespace granpipe::force_network {

StrongNetwork strong_network(const Frame& frame, const ForceContacts& forces,
                             const Networks& networks) {
  const IndexArray& ci = frame.contact_i();
  const IndexArray& cj = frame.contact_j();
  StrongNetwork out;
  out.flag = IntArray::Zero(ci.size());
  std::vector<Eigen::Index> rows;
  Eigen::Array<bool, Eigen::Dynamic, 1> touched =
      Eigen::Array<bool, Eigen::Dynamic, 1>::Zero(frame.size());
  for (Eigen::Index row : forces.edges) {
    if (!(forces.magnitude[row] > forces.mean)) continue;
    out.flag[row] = 1;
    rows.push_back(row);
    touched[ci[row]] = touched[cj[row]] = true;
  }
  out.contacts = static_cast<long>(rows.size());
  out.particles = touched.count();
  out.particles_in_largest = (touched && networks.label.array() == 0).count();
  out.largest = find_networks(frame, rows).largest();
  return out;
}

}  // namespace granpipe::force_network
