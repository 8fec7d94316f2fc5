#include "arch_statistics.hpp"

#include <numeric>

namespace granpipe::arches {

Eigen::Index ArchStatistics::arches() const {
  Eigen::Index total = 0;
  for (std::size_t s = 2; s < n.size(); ++s) total += n[s];
  return total;
}

Eigen::Index ArchStatistics::groups() const {
  return std::accumulate(n.begin(), n.end(), Eigen::Index{0});
}

ArchStatistics arch_statistics(Eigen::Index disks, const std::vector<Arch>& arches) {
  ArchStatistics st;
  st.disks = disks;
  st.n.assign(2, 0);
  Eigen::Index in_arches = 0;
  for (const Arch& a : arches) {
    const std::size_t s = a.disks.size();
    if (st.n.size() <= s) st.n.resize(s + 1, 0);
    ++st.n[s];
    in_arches += static_cast<Eigen::Index>(s);
    st.p1 += 2;
    st.p2 += static_cast<Eigen::Index>(s) - 2;
  }
  st.n[1] = disks - in_arches;
  return st;
}

}  // namespace granpipe::arches
