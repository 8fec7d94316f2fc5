#pragma once
// Where a dem run starts: a frame of a saved file (its particles and container) or a loose
// bed generated in a cylinder (loose_lattice.hpp), as the source's parameters say.
#include <string>

#include "granpipe/container.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/property_table.hpp"
#include "particles.hpp"

namespace granpipe::dem {

// Where the run starts: the particles and the container holding them.
struct Start {
  InitialState state;
  Container container;
  IndexArray id;      // the particles' ids, in the order of state
  std::string where;  // "source.params.initial_file: <file>: frame <k>"; "" for a bed
};

// The start the parameters name: initial_file (frame initial_frame) or bed, exactly one of
// them. Throws InputError naming the parameter when neither or both are given, when the
// frame is missing or not 3D, its radii missing, its species missing while the table has
// several, or when the species table lacks a species of the start.
Start start_of(const PluginContext& ctx, int species);

}  // namespace granpipe::dem
