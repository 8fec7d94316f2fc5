#pragma once
// The state of a 2D bed of hard disks in an open-top box [0, width] x [0, inf): centres,
// radii and the two supporting contacts of every disk, as the Manna-Khakhar deposition
// defines them. Plain data, so that tests can build scenes by hand.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "granpipe/container.hpp"
#include "granpipe/frame.hpp"

namespace granpipe::disks2d_tap {

// The columns a tapped frame carries beyond the particles' own: support labels
// (left, right, in the partner encoding of frame.hpp) and, per frame, the tap number, the
// half-cycle of a ramped protocol (-1 when constant) and the tap amplitude A.
Property supports_property();
Property tap_property();
Property cycle_property();
Property amplitude_property();

// What supports a disk: a disk index (>= 0), nothing, or a wall; the partner encoding of
// frame.hpp narrowed to 32 bits so that the hot loops stay small.
using PartnerCode = std::int32_t;
constexpr PartnerCode kNone = static_cast<PartnerCode>(partner::none);
constexpr PartnerCode kLeftWall = static_cast<PartnerCode>(partner::wall(Wall::XLow));
constexpr PartnerCode kRightWall = static_cast<PartnerCode>(partner::wall(Wall::XHigh));
constexpr PartnerCode kBase = static_cast<PartnerCode>(partner::wall(Wall::YLow));

constexpr bool is_disk(PartnerCode p) { return p >= 0; }
constexpr bool is_side_wall(PartnerCode p) { return p == kLeftWall || p == kRightWall; }

struct DiskPacking {
  double width = 20.0;
  std::vector<double> x, y, r;
  // First and second supporting contact in the paper's sense. A disk on the base has
  // both equal to kBase; a stable disk off the base has two; a falling disk none.
  std::vector<PartnerCode> first, second;

  std::size_t size() const { return x.size(); }
  // Appends a disk with no supports.
  void add(double xi, double yi, double ri);
  void clear_supports();

  bool on_base(std::size_t i) const { return first[i] == kBase; }
  bool stable(std::size_t i) const { return first[i] == kBase || second[i] != kNone; }
  double min_radius() const;
  double max_radius() const;
  double top() const;  // highest point of any disk, 0 when empty

  // Where disk i touches partner p (the point on the line of centres, or on the wall).
  double contact_x(std::size_t i, PartnerCode p) const;
  double contact_y(std::size_t i, PartnerCode p) const;

  // Throws InputError naming `where` on non-finite or non-positive values, disks
  // reaching outside the box, or pairs overlapping by more than tolerance * radius.
  void check(const std::string& where, double tolerance) const;

  // Fills a 2D frame: positions, radii, ids, the open-top container up to top() and the
  // left/right support labels (the left one touches the disk at the smaller x).
  void to_frame(Frame& frame) const;
  // The disks of a 2D frame in a box of the frame container's width, without supports
  // (a deposition finds them again). Throws InputError naming `where` when the frame is
  // not 2D, its box does not start at x = 0, or check(where, 1e-9) fails.
  static DiskPacking from_frame(const Frame& frame, const std::string& where);
};

}  // namespace granpipe::disks2d_tap
