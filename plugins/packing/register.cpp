#include "granpipe/plugin.hpp"
#include "packing_analyzer.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::packing::PackingAnalyzer>(
      "packing",
      "exact packing fraction of a region, number density, coordination numbers and the "
      "vertical profile phi(y) from horizontal cuts",
      granpipe::packing::schema());
}
