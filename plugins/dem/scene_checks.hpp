#pragma once
// The drive and gravity checked against the contacts and the time step before a run, as
// dt is checked against the contact time (time_step.hpp):
//   - the drive's period must span at least kMinStepsPerPeriod steps: at 50, the walls'
//     velocity changes by at most 2 pi / 50 = 13 % of its peak within a step;
//   - a sphere hit by a wall at the drive's peak speed A 2 pi f, and one resting on a wall
//     under gravity, must stay within the overlap limit (overlap_limit.hpp), the largest
//     sphere of every species that moves, against every wall;
//   - the drag -b v (background and air damping together) must take at least one step to
//     stop the lightest sphere, b dt / m <= 1: beyond, each step reverses its velocity, and
//     from 2 on the run blows up, blamed on the contacts.
// Each refusal names the parameter and says how far it may go.
#include "contact_parts.hpp"
#include "drive.hpp"
#include "granpipe/plugin.hpp"
#include "model.hpp"
#include "particles.hpp"
#include "walls.hpp"

namespace granpipe::dem {

inline constexpr double kMinStepsPerPeriod = 50.0;

// What the checks read of the scene.
struct Scene {
  const Model& model;
  const WallSet& walls;
  const InitialState& start;
  ContactLaw law;
};

// Throws InputError naming drive.frequency (steps per period) or drive (peak speed).
void check_drive(const PluginContext& ctx, const Scene& scene, const Drive& drive, double dt);
// Throws InputError naming gravity.
void check_gravity(const PluginContext& ctx, const Scene& scene, const Eigen::Vector3d& gravity);
// Throws InputError naming the larger of background_damping and air_damping.
void check_damping(const PluginContext& ctx, const Scene& scene, double background, double air,
                   double dt);

}  // namespace granpipe::dem
