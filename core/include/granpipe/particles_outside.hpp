#pragma once
// Whether a frame's particles are inside its container: the check a source makes on a
// start configuration (a data file, a saved frame) before anything runs on it, so that a
// sphere placed through a wall is refused rather than fired back in by the wall's force.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "granpipe/container.hpp"
#include "granpipe/frame.hpp"

namespace granpipe {

// How far a particle reaches beyond one side of its container.
struct ParticleOutside {
  Eigen::Index particle = 0;  // row in the frame
  Wall wall = Wall::Count;
  // Solid wall: the sphere's overlap with it (radius minus the centre's distance to the
  // wall, inward); open side: how far the centre lies beyond it.
  double depth = 0.0;
};

// The first particle (in row order) that overlaps a solid wall by more than
// `tolerance` x its radius, or whose centre lies beyond an open side. Soft-sphere packings
// press into their walls by a few percent of a radius, so touching is judged with this
// tolerance. The walls are where the frame shows them (rest geometry plus wall_offset); a
// cylinder container's walls are the cylinder and its z sides (its box's x and y sides are
// only the cell grid's bounds); periodic sides bound nothing. With `open_sides_bound` false,
// open sides bound nothing either: a saved frame's open top is no wall, and a particle
// thrown above it is still in the container.
std::optional<ParticleOutside> first_particle_outside(const Frame& frame, double tolerance,
                                                      bool open_sides_bound = true);
// The same for the frame's particles in another container (a file's own box).
std::optional<ParticleOutside> first_particle_outside(const Frame& frame,
                                                      const Container& container, double tolerance,
                                                      bool open_sides_bound = true);

// How far particle k's surface lies from the wall w of the frame's container, where the
// frame shows it (wall_offset included); negative where the particle presses into it.
double surface_gap(const Frame& frame, Eigen::Index k, Wall w);

// "at (7, 0, 2), radius 0.5: expected an overlap with the wall cylinder (radius 6.125 about
// (0, 0)) of at most 0.025 (0.05 of its radius), got 1.375": to follow the particle's name
// in a one-line message.
std::string describe(const Frame& frame, const ParticleOutside& outside, double tolerance);
std::string describe(const Frame& frame, const Container& container, const ParticleOutside& outside,
                     double tolerance);

}  // namespace granpipe
