#pragma once
// Arch size distribution of one frame and what the paper derives from it:
// end and centre particles (Eqs. 1, 2) and <z>_support (Eq. 4).
#include <vector>

#include "mutual_stability.hpp"

namespace granpipe::arches {

struct ArchStatistics {
  Eigen::Index disks = 0;
  // n[s]: number of arches of s disks, for s = 1 .. largest arch; n[1] counts the disks
  // in no arch (the paper's n(s = 1)); n[0] is unused and 0.
  std::vector<Eigen::Index> n;
  Eigen::Index p1 = 0;  // end particles, Eq. (1): 2 sum_{s>=2} n(s)
  Eigen::Index p2 = 0;  // centre particles, Eq. (2): sum_{s>=3} (s - 2) n(s)

  // Arches of two or more disks.
  Eigen::Index arches() const;
  // sum_{s>=1} n(s): arches plus disks in no arch.
  Eigen::Index groups() const;
  // Eq. (4): <z>_support = 2 [1 + sum_s n(s) / N]. It counts every disk as having two
  // supports, so it exceeds the direct count by 2 (missing supports) / N, which is
  // 2 N_base / N after a finished deposition.
  double z_eq4() const {
    return 2.0 * (1.0 + static_cast<double>(groups()) / static_cast<double>(disks));
  }
};

// `disks` is N; `arches` those of find_arches on the same frame.
ArchStatistics arch_statistics(Eigen::Index disks, const std::vector<Arch>& arches);

}  // namespace granpipe::arches
