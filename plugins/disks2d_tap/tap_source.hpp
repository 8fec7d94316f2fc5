#pragma once
// `disks2d_tap`: tapped deposits of hard disks in a box with a flat base and two side
// walls (Pugnaloni et al., "Arching in tapped deposits of hard disks"). Disks are placed
// at random (or read from a saved frame) and deposited by Manna-Khakhar pseudo-dynamics;
// each tap dilates the bed, shakes it by Monte Carlo and deposits it again. Frames carry
// the support labels.
#include <cstdint>
#include <memory>
#include <string>

#include "deposit.hpp"
#include "disk_packing.hpp"
#include "granpipe/plugin.hpp"
#include "shake.hpp"
#include "tap_schedule.hpp"

namespace granpipe::disks2d_tap {

Schema schema();

class TapSource : public Source {
 public:
  explicit TapSource(const PluginContext& ctx);

  FrameContent content() const override {
    return {
        .dim = 2,
        .columns = {supports_property(), tap_property(), cycle_property(), amplitude_property()}};
  }
  bool next(Frame& frame) override;
  Work work() const override { return {static_cast<double>(schedule_.total()), "taps", true}; }
  void finish(Results& results) override;

 private:
  void deposit();

  Progress& progress_;
  RandomStream deposition_rng_, tap_rng_;
  TapSchedule schedule_;
  DiskPacking packing_;
  std::unique_ptr<Deposit> deposit_;
  Shaker shaker_;
  bool started_ = false;
  std::int64_t tap_ = 0;
  double deposition_seconds_ = 0, tap_seconds_ = 0;
  std::string amplitude_param_;  // what sets the largest amplitude, for refusals
};

}  // namespace granpipe::disks2d_tap
