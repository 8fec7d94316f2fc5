#pragma once
// `pores`: the Delaunay pores of packings of spheres (docs/pores.md), pooled over
// frames, with a per-frame series.
#include "granpipe/plugin.hpp"
#include "measure_pores.hpp"
#include "pore_statistics.hpp"

namespace granpipe::pores {

Schema schema();

class PoresAnalyzer : public Analyzer {
 public:
  explicit PoresAnalyzer(const PluginContext& ctx);
  FrameContent needs() const override { return {.dim = 3}; }
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;

 private:
  PoreSettings settings_;
  PoreStatistics statistics_;
  StreamedTable per_frame_;
  long frames_ = 0;
};

}  // namespace granpipe::pores
