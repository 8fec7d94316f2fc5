#pragma once
// The loops of one time step, specialised at compile time by the contact's parts
// (contact_evaluator.hpp) and rotation so that a scene pays only for the physics it uses.
// The compiled combinations (kernels.cpp instantiates exactly these eight, picked by
// select_kernels through with_contact):
//
//   law      friction  rotation  rolling   use
//   Linear   off       off       off       frictionless spheres: no history, no torques
//   Linear   on        off       off       friction on non-rotating particles (sliding blocks)
//   Linear   on        on        off       the paper's spring-dashpot spheres (Brazil nut)
//   Linear   on        on        on        the same with rolling resistance
//   Hertz    (the same four)
//
// Walls (planes and a cylinder) are a short run-time list checked per particle: each
// check is a few flops with an early exit, against about ten times as many pair contacts.
//
// Threads: every loop runs over particles, and each particle's sums are taken in a fixed
// order (its own pairs in list order, then the reactions of the pairs naming it, in list
// order), never across threads, so results are bit-identical for any thread count and
// any schedule. The loops split the particles into one contiguous block per thread (the
// force loop by estimated work, the others by count): the particles are sorted in space, so a
// thread then reads and writes almost only its own neighbours' data (2.25e7 against 1.95e7
// particle-steps/s for chunks of 128 handed out dynamically, Brazil-nut scene, 2 threads on a quiet
// machine). A thread that loses its core stalls the others at the barrier: on a busy machine, one
// thread is faster, and the engine's ThreadGovernor then runs on one.
#include <cstdint>

#include "contact_evaluator.hpp"
#include "instruction_set.hpp"

namespace granpipe::dem {

// Everything the force loop reads and writes, as raw arrays (engine order of particles).
struct ForceContext {
  int n = 0;
  const double *x, *v, *omega, *radius, *inv_mass;
  const int* species;
  int species_count;
  const LoopMaterial* pair_material;  // species x species
  // Walls: planes then (optionally) the cylinder, in slot order.
  int planes;
  const int* plane_axis;
  const double* plane_sign;
  const double* plane_position;  // current (rest + offset)
  bool cylinder;
  double cylinder_x, cylinder_y, cylinder_radius;  // current axis and radius
  const LoopMaterial* wall_material;               // slot x species
  Vec3 wall_velocity;                              // at the velocities' time (half step)
  double** wall_history;                           // per slot, 3 x n (friction only)
  double** wall_rolling_history;                   // per slot, 3 x n (rolling only)
  // Recording (for frames): per slot, normal and tangential force on the particle, 3 x n;
  // null when not recording.
  double** wall_normal_record;
  double** wall_tangential_record;
  // The half list.
  const std::int32_t *first, *partner, *owner, *reaction_slot;
  const double* work_before;  // per particle, n+1: where the threads' shares start
  double* history;            // 3 per pair: the tangential displacement
  double* rolling_history;    // 3 per pair: the rolling angle (rolling only)
  double* incoming;           // 3 or 6 per slot, by partner (see NeighborList)
  double background_damping;
  double air_damping;  // on the slip velocity against wall_velocity
  double dt_history;
  // The deepest overlap a sound contact reaches, as a fraction of the smaller radius (of
  // the particle, against a wall): the loop returns how far the deepest contact goes past it.
  double overlap_limit;
  int threads;
  // Out: force and sum of n x F_t per particle (own pairs and walls only).
  double *force, *spin_sum;
};

// The kicks and the drift of velocity Verlet, with the gather of the reactions.
struct KickContext {
  int n = 0;
  double *x, *v, *omega, *force, *torque;
  const double *radius, *inv_mass, *inv_inertia, *spin_sum;
  const double* x_build;
  double* incoming;  // read, and cleared unless keep_reactions
  // The step a frame shows: its contacts' forces are read from the slots after the step
  // (the engine clears them before the next force pass).
  bool keep_reactions = false;
  const std::int32_t* reverse_first;
  Vec3 gravity;
  double dt;
  int threads;
};

struct Kernels {
  // Returns the largest overlap - overlap_limit x (smaller) radius over the contacts, a
  // length: > 0 when a contact went deeper than a sound run allows. Taken as a running
  // maximum per lane and thread, it costs a few operations per batch of pairs and changes
  // no force.
  double (*forces)(const ForceContext&);
  // The end of a step: reactions added to force/torque (their slots cleared unless kept), then
  // v += dt/2 a (w likewise).
  void (*finish_step)(const KickContext&);
  // The start of a step: v += dt/2 a, x += dt v (w likewise); returns the largest squared
  // displacement since the last list build.
  double (*start_step)(const KickContext&);
  // finish_step then start_step, in one sweep (bit-identical to the two), but with force
  // and torque left as they were: the next force pass overwrites force, and a run ends
  // with finish_step, which stores both.
  double (*finish_and_start)(const KickContext&);
  int reaction_stride;
};

// kernels.cpp is compiled once per instruction set (instruction_set.hpp); each copy's
// entry point: the kernels of one combination. friction=false with rotation=true is served
// by the frictionless kernels (no tangential force, so no torque); rolling needs friction
// and rotation (the Engine refuses it otherwise).
namespace baseline {
Kernels select_kernels(ContactLaw law, bool friction, bool rotation, bool rolling);
}
namespace avx2 {
Kernels select_kernels(ContactLaw law, bool friction, bool rotation, bool rolling);
}
namespace avx512 {
Kernels select_kernels(ContactLaw law, bool friction, bool rotation, bool rolling);
}

// The kernels of one combination on one path (resolved: not Auto, and runs_here).
Kernels select_kernels(InstructionSet path, ContactLaw law, bool friction, bool rotation,
                       bool rolling);

}  // namespace granpipe::dem
