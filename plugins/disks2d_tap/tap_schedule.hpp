#pragma once
// The sequence of taps of a run: which amplitude each tap has, which half-cycle of an
// annealing it belongs to, and whether its configuration is saved.
#include <cstdint>

namespace granpipe::disks2d_tap {

struct TapStep {
  double amplitude = 1.0;
  std::int64_t cycle = -1;  // annealed: half-cycle index (even: A rising, odd: falling)
  bool save = false;
};

class TapSchedule {
 public:
  // `equilibration` taps at A, then `production` taps saving every `save_every`-th.
  static TapSchedule constant(double A, std::int64_t equilibration, std::int64_t production,
                              std::int64_t save_every);
  // The same, after cooling: `taps_per_step` taps at each of the amplitudes
  // from, from - step, from - 2 step, ... that lie above A (none saved). A bed brought
  // slowly down from the disordered regime ends in one layered domain, where a bed tapped
  // at A from a random deposit freezes its domains.
  static TapSchedule cooled_constant(double from, double step, std::int64_t taps_per_step, double A,
                                     std::int64_t equilibration, std::int64_t production,
                                     std::int64_t save_every);
  // `cycles` times: A rises from A_min to A_max in `steps` steps of `taps_per_step` taps
  // (A_min + k dA, k = 1..steps), then falls back through the same levels, each computed
  // from its index so that it is the same double both ways. Half-cycle
  // 0 is the very first rise, which the paper keeps apart. Saves every `save_every`-th
  // tap of each step.
  static TapSchedule annealed(double A_min, double A_max, std::int64_t steps,
                              std::int64_t taps_per_step, std::int64_t cycles,
                              std::int64_t save_every);

  // The counts the factories above multiply and add, in doubles, for the caller to check
  // against the 64-bit range first (sums and products of large counts wrap round).
  static double cooling_levels(double from, double step, double A);
  static double annealed_taps(double steps, double taps_per_step, double cycles) {
    return 2.0 * cycles * steps * taps_per_step;
  }

  std::int64_t total() const { return total_; }
  // Tap number `tap`, counted from 1 to total().
  TapStep at(std::int64_t tap) const;

 private:
  bool annealed_ = false;
  double A_ = 1.0, A_min_ = 1.0, A_max_ = 1.0;
  std::int64_t equilibration_ = 0, steps_ = 1, taps_per_step_ = 1, save_every_ = 1;
  std::int64_t total_ = 0;
  double cool_from_ = 1.0, cool_step_ = 0.0;
  std::int64_t cooling_taps_ = 0;  // taps before the constant part (taps_per_step_ each level)
};

}  // namespace granpipe::disks2d_tap
