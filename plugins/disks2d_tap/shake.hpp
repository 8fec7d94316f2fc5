#pragma once
// The tap of the paper: heights multiplied by the amplitude A, then Monte Carlo loops in
// which every disk in turn (in index or shuffled order: visit_order.hpp) tries a jump of
// random length uniform in (0, A - 1) in a random direction, refused when it would
// overlap another disk, a side wall or the base.
#include <cstdint>
#include <vector>

#include "disk_grid.hpp"
#include "disk_packing.hpp"
#include "granpipe/params.hpp"
#include "granpipe/random.hpp"
#include "visit_order.hpp"

namespace granpipe::disks2d_tap {

// What the dilation multiplies: centre heights (y -> A y, the paper's wording), or
// heights above the lowest possible centre (y - r_min -> A (y - r_min)), which keeps
// disks on the base there. Both only ever separate disks.
enum class Dilation : std::uint8_t { CentreHeight, HeightAboveContact };
inline ChoiceNames<Dilation> choice_names(Dilation) {  // parameter dilation
  return {{"centre_height", Dilation::CentreHeight},
          {"height_above_contact", Dilation::HeightAboveContact}};
}

// Loops per tap that put the order-disorder transition where the paper has it (between
// A = 1.10 and 1.15); the paper's "about 20" of its own, undefined, loops mix as much as
// about 60 of these, which try one jump per disk (docs/disks2d_tap.md, "How much the tap
// mixes").
inline constexpr int kPaperMatchedMcLoops = 60;

struct ShakeStats {
  std::uint64_t trials = 0, accepted = 0;
};

class Shaker {
 public:
  Shaker(int mc_loops, Dilation dilation, McOrder order = McOrder::Index)
      : loops_(mc_loops), dilation_(dilation), order_(order) {}

  // Taps `packing` with amplitude A and clears every support label. A <= 1 is no tap:
  // nothing moves and the labels stay.
  void tap(DiskPacking& packing, double A, RandomStream& rng);
  const ShakeStats& stats() const { return stats_; }

 private:
  int loops_;
  Dilation dilation_;
  VisitOrder order_;
  DiskGrid grid_;
  std::vector<int> cell_;
  ShakeStats stats_;
};

}  // namespace granpipe::disks2d_tap
