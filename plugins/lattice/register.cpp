#include "granpipe/plugin.hpp"
#include "lattice_source.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_source<granpipe::lattice::LatticeSource>(
      "lattice", "square, triangular, sc, bcc, fcc and hcp crystals of touching particles",
      granpipe::lattice::schema());
}
