#pragma once
// Manna-Khakhar pseudo-dynamics: disks move one at a time, falling a length delta when
// unsupported and rolling an arc length delta over their single support, until every
// disk rests on two supporting contacts or on the base. Falls and rolls that would
// overlap stop exactly at contact (solved analytically, see contact_geometry.hpp).
//
// Only unstable disks cost time: the engine keeps the set of disks that can move and,
// for every disk, the list of disks it supports, so a move re-examines just those.
#include <cstdint>
#include <span>
#include <vector>

#include "disk_grid.hpp"
#include "disk_packing.hpp"
#include "granpipe/params.hpp"
#include "granpipe/random.hpp"

namespace granpipe::disks2d_tap {

// How delta measures a roll: the arc length of the rolling disk's centre path (radius
// r_i + r_s) or of the contact point over the support's surface (radius r_s).
enum class RollMeasure : std::uint8_t { CentrePath, SupportSurface };
// Which disk moves next: a random unstable disk each move, or sweeps in which every
// disk unstable at the sweep's start moves once, in shuffled order.
enum class MoveOrder : std::uint8_t { Random, Sweeps };
// What happens to the supports a disk gives when it moves: dropped on any displacement,
// or kept while the two still touch (to 1e-9 of the radius) and the pair stays stable.
enum class SupportUpdate : std::uint8_t { Drop, KeepTouching };

// The names pipelines give them (parameters roll_measure, move_order, support_update).
inline ChoiceNames<RollMeasure> choice_names(RollMeasure) {
  return {{"centre_path", RollMeasure::CentrePath},
          {"support_surface", RollMeasure::SupportSurface}};
}
inline ChoiceNames<MoveOrder> choice_names(MoveOrder) {
  return {{"sweeps", MoveOrder::Sweeps}, {"random", MoveOrder::Random}};
}
inline ChoiceNames<SupportUpdate> choice_names(SupportUpdate) {
  return {{"drop", SupportUpdate::Drop}, {"keep_touching", SupportUpdate::KeepTouching}};
}

struct DepositOptions {
  double delta = 0.01;
  RollMeasure measure = RollMeasure::CentrePath;
  MoveOrder order = MoveOrder::Sweeps;
  SupportUpdate update = SupportUpdate::Drop;
};

// What one move did.
enum class Move : std::uint8_t {
  None,             // the disk was stable: nothing to do
  Fall,             // fell delta freely
  LandOnDisk,       // fell onto a disk: its first support
  LandOnBase,       // fell onto the base: stuck there
  Roll,             // rolled delta over its support
  RollOff,          // reached its support's height: lost it
  RollOntoBase,     // rolled onto the base: stuck there
  RollToRest,       // met a second contact forming a stable pair
  RollToNewSupport  // met a contact forming an unstable pair: the lower is the new support
};

struct DepositStats {
  std::uint64_t falls = 0, rolls = 0;
  std::uint64_t moves() const { return falls + rolls; }
};

class Deposit {
 public:
  // Works on `packing` in place; reads its positions and support labels now.
  Deposit(DiskPacking& packing, DepositOptions options);

  // Re-reads the packing after it was changed outside (a tap): rebuilds the grid, the
  // supported-by lists and the set of unstable disks. Disks touching the base get the
  // base as support.
  void reset();

  // One fall or roll of disk i.
  Move move(std::int32_t i);
  // Moves disks (in the configured order) until every disk is stable or on the base.
  void run(RandomStream& rng);

  bool done() const { return unstable_.empty(); }
  const std::vector<std::int32_t>& unstable() const { return unstable_; }
  std::span<const std::int32_t> supported_by(std::int32_t j) const {
    return {held_.data() + static_cast<std::size_t>(j) * capacity_,
            held_count_[static_cast<std::size_t>(j)]};
  }
  const DepositStats& stats() const { return stats_; }
  const DepositOptions& options() const { return options_; }

 private:
  Move fall(std::int32_t i);
  Move roll(std::int32_t i);
  // Places disk i at (x, y), keeping the grid in step; true when it moved.
  bool place(std::int32_t i, double x, double y);
  // After i moved: updates the supports of every disk resting on i.
  void release_held(std::int32_t i);
  void hold(std::int32_t i, PartnerCode by);    // i is supported by `by`
  void unhold(std::int32_t i, PartnerCode by);  // i no longer is
  void set_unstable(std::int32_t i, bool unstable);
  bool pair_stable(std::int32_t i, PartnerCode a, PartnerCode b) const;
  void note_zero_move(std::int32_t i, bool moved);
  // After disk i rolled: the clearances cached for the disks above it may be too long.
  void forget_clearance_above(std::int32_t i);
  const std::pair<double, double>& roll_rotation(double divisor);
  // A move shorter than this, along a path of this radius, leaves a disk where it is: the
  // contact ahead touches it already.
  double stay_distance(double radius) const;

  DiskPacking& p_;
  DepositOptions options_;
  DiskGrid grid_;
  double max_radius_ = 0;
  std::vector<int> cell_;           // grid cell of each disk
  std::size_t capacity_ = 0;        // most disks one disk can touch
  std::vector<std::int32_t> held_;  // disks supported by j: held_[j*capacity_ + k]
  std::vector<std::uint32_t> held_count_;
  std::vector<std::int32_t> unstable_;  // disks that can move, in no order
  std::vector<std::int32_t> slot_;      // index in unstable_, or -1
  std::vector<std::int32_t> sweep_;     // the disks of the current sweep
  std::vector<std::uint16_t> stalled_;  // consecutive moves of a disk that went nowhere
  // A falling disk's free drop known from its last search below it (0: unknown). Only
  // rolls can bring an obstacle closer (falls are vertical and downward), and every
  // roll resets the clearances above it, so a fall within the clearance needs no search.
  std::vector<double> clearance_;
  double lookahead_ = 0;     // how far below a fall's search reaches
  double position_ulp_ = 0;  // rounding of the largest coordinate in the box
  double cached_divisor_ = -1;
  std::pair<double, double> cached_rotation_{1.0, 0.0};  // cos, sin of the roll angle
  DepositStats stats_;
};

}  // namespace granpipe::disks2d_tap
