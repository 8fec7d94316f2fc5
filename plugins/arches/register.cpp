#include "arches_analyzer.hpp"
#include "granpipe/plugin.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::arches::ArchesAnalyzer>(
      "arches",
      "mutual stability and arches of 2D pseudo-dynamics packings: n(s), p1, p2, <z>_support, "
      "spans, SVG pictures",
      granpipe::arches::schema());
}
