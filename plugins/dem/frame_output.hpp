#pragma once
// The engine's state as a granpipe::Frame, built only when a frame is emitted.
#include "engine.hpp"
#include "granpipe/frame.hpp"

namespace granpipe::dem {

// Fills `frame` (3D; rows in the caller's original particle order, id = that index):
// position, radius, id, species, velocity, angular_velocity; the container displaced to
// the current time; time and step; and the contact table, one row per touching pair
// (i < j) and per particle-wall contact (j = partner::wall(w)), sorted by (i, j), with
// overlap, normal_force and tangential_force on i, and the contact point (middle of the
// overlap). The forces are those of the engine's last force evaluation, the ones the
// particles felt. Throws InternalError when the engine has walls and did not record that
// evaluation (call Engine::record_contacts(true) before the last step), and frees those
// records once read (Engine::release_contact_records): a second frame of the same step
// throws too.
void fill_frame(Engine& engine, Frame& frame);

}  // namespace granpipe::dem
