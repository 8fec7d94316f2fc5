#include "granpipe/plugin.hpp"
#include "pores_analyzer.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::pores::PoresAnalyzer>(
      "pores",
      "Delaunay pores of packings of spheres: size and volume distributions P(xi), "
      "xi^3 P(xi), nu and the shares of Bernal's canonical holes; each sphere's Voronoi "
      "(Laguerre) cell volume and local packing fraction",
      granpipe::pores::schema());
}
