#pragma once
// `packing`: packing fraction of a region (exact, cut particles included), number
// density, coordination numbers from contacts by distance, and the vertical profile of
// the area fraction of horizontal cuts (stereology), per frame and averaged over frames.
#include <cstdint>
#include <string>
#include <vector>

#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/log.hpp"
#include "granpipe/mean_profile.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/ramp_means.hpp"
#include "granpipe/region.hpp"

namespace granpipe::packing {

Schema schema();

enum class Top : std::uint8_t { Auto, Surface, LowestSurface, Container };
inline ChoiceNames<Top> choice_names(Top) {  // parameter top
  return {{"auto", Top::Auto},
          {"surface", Top::Surface},
          {"lowest_surface", Top::LowestSurface},
          {"container", Top::Container}};
}

struct PackingSettings {
  double tolerance = kDefaultContactTolerance;  // relative contact tolerance
  double exclude_bottom = 0.0;                  // mean diameters above the base
  double exclude_top = 0.0;    // mean diameters below the top (surface or container)
  double exclude_sides = 0.0;  // mean diameters from each lateral side
  Top top = Top::Auto;
  double profile_step = 0.05;  // mean diameters; 0: no profile
  double cuts_step = 0.01;     // mean diameters; 0: no phi_cuts
  // Where these sit in the pipeline ("analyzers[1].params"), so that messages name them.
  std::string params = "packing";
};

// What one frame measures.
struct PackingMeasurement {
  Region region;
  double diameter = 0.0;        // mean particle diameter, the unit of the settings
  double phi = 0.0;             // exact volume (area) fraction of the region
  double number_density = 0.0;  // centres in the region per unit volume (area)
  long centres = 0;             // particles whose centres lie in the region
  double z_mean = 0.0;          // contacts per particle centred in the region
  double z_mean_with_walls = 0.0;
  double phi_cuts = 0.0;        // mean cut fraction over the region's height (NaN: no cuts)
  std::vector<double> profile;  // cut fractions at (k + 1/2) profile_step above the base
};

// The region of a frame: the container shrunk by the settings' margins, its top at the
// container's top, the highest particle top or the lowest point of the free surface.
// Throws InputError when it is empty.
Region packing_region(const Frame& frame, const PackingSettings& settings);

// Throws InputError for a frame without particles (the analyzer skips those).
PackingMeasurement measure_packing(const Frame& frame, FrameCache& cache,
                                   const PackingSettings& settings);

class PackingAnalyzer : public Analyzer {
 public:
  explicit PackingAnalyzer(const PluginContext& ctx);
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;
  // Each particle's number of particle contacts (walls not counted), for the analyzers
  // after this one and the writers.
  std::vector<Property> publishes() const override { return {coordination_property()}; }
  void publish(PropertyTable& columns) override {
    columns.get<IntArray>("coordination") = coordination_;
  }
  static Property coordination_property() {
    return {"coordination",
            Scope::Particle,
            ValueType::Small,
            1,
            "",
            "contacts with other particles (by distance, the analyzer's tolerance)"};
  }

 private:
  IntArray coordination_;  // of the last frame consumed
  PackingSettings settings_;
  Log& log_;
  int dim_ = 3;
  long frames_ = 0, skipped_ = 0;
  FirstFrameWarning centreless_;
  FirstFrameWarning untouching_;  // frames of several particles without one contact
  FirstFrameWarning coarse_;      // positions rounded coarser than the contact tolerance
  RunningMean phi_, density_, z_, z_walls_, phi_cuts_;
  RampMeans by_ramp_{{"phi", "z_mean"}};
  StreamedTable per_frame_;
  MeanProfile profile_;  // the vertical profile, over frames
};

}  // namespace granpipe::packing
