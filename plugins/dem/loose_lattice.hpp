#pragma once
// A loose starting bed: equal spheres on stacked square layers (every other layer shifted
// by half a spacing) inside a vertical cylinder, each nudged sideways at random so that
// the bed does not settle as a crystal. The gravity-settled packing of such a bed is how
// the Brazil-nut scene and the reference LAMMPS runs prepare their beds. An intruder (the
// Brazil nut) may sit on the axis just above the base, the lattice built around it.
#include <cstdint>

#include "particles.hpp"

namespace granpipe::dem {

struct LooseLattice {
  int count = 0;  // spheres
  double radius = 0.5;
  double cylinder_radius = 0.0;  // axis through (0, 0)
  double base = 0.0;             // z of the base
  double spacing = 2.06;         // between neighbours in a layer and between layers (> 2 radius)
  double jitter = 0.01;          // largest sideways nudge
  double intruder_radius = 0.0;  // > 0: one sphere of species 1 on the axis, tag 0
  std::uint64_t seed = 1;
};

// The narrowest cylinder that holds a sphere of this radius nudged by up to `jitter`.
double narrowest_cylinder_radius(double radius, double jitter);

// `count` spheres of species 0 (and the intruder, first), at rest. Throws InputError when
// the spacing is not larger than a diameter plus twice the jitter, or when no sphere (or
// not the intruder) fits in the cylinder.
InitialState loose_lattice(const LooseLattice& spec);

}  // namespace granpipe::dem
