#pragma once
// `pores`: the Delaunay pores of packings of spheres (docs/pores.md) and the probability
// P0 that a random probe overlaps no sphere, pooled over frames, with a per-frame series.
#include <optional>
#include <string>
#include <vector>

#include "granpipe/plugin.hpp"
#include "measure_pores.hpp"
#include "pore_statistics.hpp"
#include "void_probability.hpp"
#include "volume_distribution.hpp"

namespace granpipe::pores {

Schema schema();

class PoresAnalyzer : public Analyzer {
 public:
  explicit PoresAnalyzer(const PluginContext& ctx);
  FrameContent needs() const override { return {.dim = 3}; }
  std::vector<Property> publishes() const override;
  void publish(PropertyTable& columns) override;
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;

 private:
  PoreSettings settings_;
  Log& log_;
  void probe_voids(const Frame& frame, double mean_radius, const std::string& where);
  void add_frame_distributions(const Frame& frame, const PoreMeasurement& m);
  void add_pore_rows(const Frame& frame, const PoreMeasurement& m);
  void keep_cells(const Frame& frame, const PoreMeasurement& m);
  void warn_if_coarse(const Frame& frame, const std::string& where);

  PoreStatistics statistics_;
  VolumeDistribution volumes_;
  Seeds seeds_;
  long probes_;  // per frame; 0: P0 not measured
  VoidProbability void_probability_;
  std::string sigma_max_param_;
  StreamedTable per_frame_;
  // With frame_distributions: P(xi) and rho_v(v) of every frame (the paper's Fig. 10).
  std::optional<StreamedTable> frame_xi_, frame_v_;
  // With pore_table: a row per pore of every frame.
  std::optional<StreamedTable> pore_table_;
  // Of the last frame consumed, for publish().
  Eigen::ArrayXd cell_volume_, local_fraction_;
  long undefined_volumes_ = 0, hidden_spheres_ = 0;
  double bin_width_, xi_max_, v_bin_width_, v_max_;
  long frames_ = 0;
  long frames_without_spheres_ = 0;  // in the region: pores_per_sphere undefined
  bool warned_coarse_ = false;
};

}  // namespace granpipe::pores
