#pragma once
// The observables of the Brazil-nut papers' Figs. 3, 8 and 10, per frame: the height of the
// intruder (the largest particle) and of the centre of mass of the other particles above
// the base, which moves with the container, and the mean coordination number from the
// frame's contact table (particle pairs only, each contact counted for both particles).
#include "granpipe/plugin.hpp"

namespace granpipe::intruder {

struct BedState {
  double intruder_height = 0.0;  // intruder centre above the base
  double bed_height = 0.0;       // centre of mass of the other particles above the base
  double coordination = 0.0;     // 2 (particle-particle contacts) / particles
};

// Throws InputError naming `where` for a frame of fewer than two particles.
BedState measure_bed(const Frame& frame, const std::string& where);

class IntruderAnalyzer : public Analyzer {
 public:
  explicit IntruderAnalyzer(const PluginContext& ctx);
  FrameContent needs() const override { return {.dim = 3, .contacts = true}; }
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;

 private:
  StreamedTable per_frame_;
  long frames_ = 0;
};

}  // namespace granpipe::intruder
