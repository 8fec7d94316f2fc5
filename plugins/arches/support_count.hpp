#pragma once
// Direct count of supporting contacts from the support labels, independent of the arch
// search: every distinct supporting partner of a disk is one contact, the base included
// once, and a mutual contact (shared by two disks) is one contact, not two.
#include "granpipe/frame.hpp"
#include "mutual_stability.hpp"

namespace granpipe::arches {

struct SupportCount {
  Eigen::Index disks = 0;
  Eigen::Index base_disks = 0;    // disks with the base among their supports
  Eigen::Index supports = 0;      // sum over disks of k_i, its distinct supporting partners
  Eigen::Index mutual_pairs = 0;  // pairs of mutually stable disks

  // Distinct supporting contacts.
  Eigen::Index contacts() const { return supports - mutual_pairs; }
  // Sum over disks of (2 - k_i): one per base disk in a finished deposition, plus what
  // unstable disks lack.
  Eigen::Index missing_supports() const { return 2 * disks - supports; }
  // <z>_support counted directly: each contact belongs to two disks.
  double z_direct() const {
    return 2.0 * static_cast<double>(contacts()) / static_cast<double>(disks);
  }
};

SupportCount count_supports(const Supports& supports);

}  // namespace granpipe::arches
