#pragma once
// Mutual stability and arches of a 2D packing built by pseudo-dynamics (support labels).
// Two disks A and B are mutually stable when A is the left support of B and B the right
// support of A (or the reverse); arches are the chains of mutually stable disks.
#include <cstdint>
#include <string>
#include <vector>

#include "granpipe/frame.hpp"

namespace granpipe::arches {

// Support labels of a 2D pseudo-dynamics packing: the particle column "supports" that a
// source such as disks2d_tap provides, the left and right partner of each disk in the
// partner encoding (frame.hpp).
Property supports_property();
struct Supports {
  IndexArray left, right;
  // The labels of a frame that carries them (check_supports first).
  static Supports of(const Frame& frame);
};

// One arch: its disks from the left end to the right end (at least two).
struct Arch {
  std::vector<Eigen::Index> disks;
  // Horizontal span: projection on the x axis of the segment joining the centres of the
  // two end disks, in length units (minimum image along a periodic x axis).
  double span = 0.0;
};

// Checks that `frame` is 2D and carries valid support labels: each is a disk index
// other than the disk itself, partner::none, or the left wall, right wall or base; and
// no disk has one disk as both its left and right support. Throws InputError naming
// `where` otherwise.
void check_supports(const Frame& frame, const std::string& where);

// Checks that each support touches its disk, by the rule the h5md source applies to a
// contact: a supporting disk (or wall) whose surface is more than the smaller radius away
// is no contact under any rounding (a label naming a disk 6 diameters off passed, a 1 %
// "detached support fraction" its only trace). Throws InputError naming `where`, the label
// and the gap. For labels that passed check_supports.
void check_supports_touch(const Frame& frame, const std::string& where);

// Checks that each support is on its side: a left support is the left wall, the base or a
// disk whose centre is not to the right of the disk's (along a periodic x, the nearest
// image), and the mirror for a right one. A right wall labelled as a left support, or two
// disks naming each other as right supports, counted one contact twice or made a
// supported arch end look detached, exit 0. Throws InputError naming `where`, the label
// and where the support is. For labels that passed check_supports.
void check_support_sides(const Frame& frame, const std::string& where);

// The disk mutually stable with disk i on its right: j = right[i] with left[j] == i,
// or partner::none.
std::int64_t right_mutual_partner(const Supports& supports, Eigen::Index i);

// The per-particle column the arches analyzer publishes: the index of the arch holding
// each disk in its frame (arches in the order find_arches gives), -1 for none.
Property arch_property();
IndexArray arch_of_each_disk(Eigen::Index disks, const std::vector<Arch>& arches);

// Every arch of a frame whose supports passed check_supports. Throws InputError naming
// `where` when labels close a ring of mutual supports (no chain has two ends).
std::vector<Arch> find_arches(const Frame& frame, const std::string& where);

}  // namespace granpipe::arches
