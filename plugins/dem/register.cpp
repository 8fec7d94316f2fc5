#include "dem_source.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_source<granpipe::dem::DemSource>(
      "dem",
      "soft-sphere DEM (linear or Hertz contacts, friction, vibrated walls) from a saved frame",
      granpipe::dem::schema());
}
