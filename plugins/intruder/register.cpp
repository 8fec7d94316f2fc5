#include "intruder_analyzer.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::intruder::IntruderAnalyzer>(
      "intruder",
      "Brazil-nut observables per frame: intruder and bed heights above the base and velocities, "
      "coordination, stage (compression or expansion)",
      granpipe::Schema{});
}
