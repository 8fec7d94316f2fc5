#pragma once
// Is a saved start sound? A run from it would otherwise fire a sphere that sits outside its
// container back in at a speed no scene produces, or blow two deeply overlapping spheres
// apart, and end with exit 0.
#include <array>
#include <string>

#include "drive.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/property_table.hpp"
#include "model.hpp"
#include "particles.hpp"

namespace granpipe::dem {

// Throws InputError, its message starting with `where`, when the frame holds no particle,
// a sphere reaching past a wall of its container (the walls at their stated place) by more
// than kMaxOverlapFraction of its radius (overlap_limit.hpp), or two spheres overlapping by
// more than that fraction of the smaller radius. Contacts within it, as a saved frame of a
// run holds them, pass.
void check_start_frame(const Frame& frame, const std::string& where);

// Throws InputError starting with `where` when the start's container is not where the drive
// puts it at t = 0 (displaced, or moving at another velocity than the drive's then; at rest
// starts any drive), within rounding: the run starts its walls there and its clock at 0. `dt` and
// `radius` (the smallest) scale what rounding is.
void check_start_motion(const Container& container, const Drive& drive, double dt, double radius,
                        const std::string& where);

// Throws InputError starting with `where` when a sphere of the start moves farther in one
// step of `dt` than kMaxOverlapFraction of its radius (10^200 gave "overlaps wall ... by
// inf %" at step 1, naming neither the file nor the speed): a step that long cannot resolve
// its contacts. `id` names the particles in the message.
void check_start_speeds(const InitialState& start, const IndexArray& id, double dt,
                        const std::string& where);

// Throws InputError starting with `where` when a particle of a fixed species (held by the
// container) starts moving otherwise than the container or spinning: the run sets it moving
// with the container, dropping what the start said (exit 0). `held_velocities`: the start
// container's velocity, and the drive's at t = 0 (a container stated at rest starts any
// drive, its held particles then set off with it). Within rounding, 1e-9 of that speed and
// of a radius a step.
void check_fixed_held(const InitialState& start, const IndexArray& id, const Model& model,
                      const std::array<Eigen::Vector3d, 2>& held_velocities, double dt,
                      const std::string& where);

}  // namespace granpipe::dem
