#pragma once
// A soft-sphere DEM run in 3D: particles, walls, contact law, time stepping. Rolling
// resistance acts when a material has mu_roll > 0 (it needs friction and rotation).
//
// Time step (velocity Verlet, as LAMMPS' nve/sphere):
//   v(t+dt/2) = v(t) + dt/2 a(t),    w(t+dt/2) = w(t) + dt/2 alpha(t)
//   x(t+dt)   = x(t) + dt v(t+dt/2)
//   [rebuild the neighbour list if a particle moved more than skin/2 since the last build]
//   forces and torques from x(t+dt), v(t+dt/2), w(t+dt/2), the walls at D(t+dt) moving
//   with V(t+dt/2) (velocity-dependent forces see the half-step velocities, of particles
//   and walls alike), tangential histories advanced by dt
//   v(t+dt) = v(t+dt/2) + dt/2 a(t+dt),  w(t+dt) = w(t+dt/2) + dt/2 alpha(t+dt)
// with a = F/m + g (F: contacts and background damping -b v) and alpha = T/I, I = 2/5 m R^2
// (solid spheres; spheres need no orientation). The forces at t = 0 are evaluated when
// the engine is made, without advancing any history.
//
// Particles of a fixed species (Model::fixed) are held by the container: after each drift
// they are put back at their starting position displaced with the walls, D(t+dt), moving
// with the walls' velocity at the half step, without spin; the forces on them are unused.
//
// The hot loop touches only the engine's arrays; frame_output.hpp turns the state into a
// granpipe::Frame when one is wanted.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "contact_evaluator.hpp"
#include "instruction_set.hpp"
#include "kernels.hpp"
#include "model.hpp"
#include "neighbor_list.hpp"
#include "particles.hpp"
#include "thread_governor.hpp"
#include "walls.hpp"

namespace granpipe::dem {

struct Settings {
  double dt = 0.0;
  Eigen::Vector3d gravity = -Eigen::Vector3d::UnitZ();  // acceleration
  ContactLaw law = ContactLaw::Linear;
  bool friction = true;
  bool rotation = true;
  double skin = 0.2;                // neighbour-list margin, in smallest particle diameters
  double background_damping = 0.0;  // b of Eq. (7): force -b v on every particle
  // The interstitial air's drag, -b_air (v - V): the slip velocity is taken against the
  // container's velocity V, as if the air moved with the container (incompressible air in
  // a closed-bottom cylinder, its flow through the pores neglected).
  double air_damping = 0.0;
  int threads = 1;  // the most the loops use
  // Fewer threads while they are measured to run faster (a busy machine): thread_governor.hpp.
  bool adapt_threads = true;
  // The loops' path; Auto: resolve() in instruction_set.hpp picks it.
  InstructionSet instruction_set = InstructionSet::Auto;

  // Throws InputError naming the setting on a non-finite or out-of-range value.
  void check() const;
};

// Wall-clock seconds spent in each part of the time step since the engine was made. Pairs
// and walls are one fused loop (each particle's wall checks follow its pairs), so they are
// timed together.
struct StepProfile {
  double forces = 0.0;     // pair and wall forces
  double integrate = 0.0;  // reactions gathered, kicks and drift
  double neighbour = 0.0;  // list rebuilds (with the spatial sort)
  std::int64_t rebuilds = 0;
  std::int64_t steps_on_fewer_threads = 0;  // than Settings::threads (thread_governor.hpp)
};

class Engine {
 public:
  // Throws InputError on invalid settings, materials, walls or particles (sizes, NaN,
  // radius <= 0, species out of range, two centres at one point), naming what and which
  // particle.
  Engine(const Model& model, const WallSet& walls, const Settings& settings,
         const InitialState& initial);

  // Advances `steps` time steps. Allocates nothing except when a neighbour-list rebuild
  // needs more room than any before. Throws BlowUp (blow_up.hpp) at the end of the first
  // step whose deepest contact goes past kMaxOverlapFraction (overlap_limit.hpp), naming
  // it. (The start is not checked here: the dem source refuses unsound starts with the
  // file's name, and tests of the neighbour list use random overlapping spheres.)
  void run(std::int64_t steps);

  // From the next force evaluation on, keep the wall contact forces (pair forces are
  // always kept) so that a frame can show every contact. Turned on at step 0, it records
  // the initial forces at once.
  void record_contacts(bool on);
  // True when the forces of the current state were evaluated while recording.
  bool contacts_recorded() const { return recorded_step_ == step_; }
  // Frees the recorded wall forces once a frame has read them (they are as large as the
  // particle arrays); recording, if on, goes on from the next force evaluation.
  void release_contact_records();
  // Changes the container's motion from now on (the drive's own start time applies).
  void set_drive(const Drive& drive);

  double time() const { return static_cast<double>(step_) * settings_.dt; }
  std::int64_t step() const { return step_; }
  const Settings& settings() const { return settings_; }
  // The path the loops take (settings().instruction_set resolved).
  InstructionSet instruction_set() const { return instruction_set_; }
  const Model& model() const { return model_; }
  const WallSet& walls() const { return walls_; }
  const Particles& particles() const { return p_; }
  const NeighborList& neighbors() const { return list_; }
  const StepProfile& profile() const { return profile_; }
  // The walls' displacement at the current time.
  Eigen::Vector3d wall_offset() const { return walls_.drive().offset(time()); }
  // The neighbour-list skin as a length.
  double skin() const { return list_.skin(); }
  // Wall forces of the last recorded evaluation: per active wall slot, normal and
  // tangential force on each particle (engine order; zero when not touching).
  const std::vector<Vectors>& recorded_wall_normal() const { return wall_normal_; }
  const std::vector<Vectors>& recorded_wall_tangential() const { return wall_tangential_; }

  // The tangential displacement of particle tag_a against tag_b, as seen from tag_a:
  // nothing when the two are not in the neighbour list, zero when listed but not touching.
  std::optional<Vec3> pair_history(std::int32_t tag_a, std::int32_t tag_b) const;
  // The same against wall w (nothing when w is not an active wall or without friction).
  std::optional<Vec3> wall_history(std::int32_t tag, Wall w) const;
  // The engine index of the particle with this tag (the engine reorders particles).
  int index_of(std::int32_t tag) const;

 private:
  void load_particles(const InitialState& initial);
  // The particles of fixed species become pinned, at rest where they start.
  void hold_fixed_species();
  void prepare_materials();
  void refuse_coincident_centres() const;
  // The neighbour-list rebuild, with the spatial sort (pinned particles found again).
  void rebuild();
  // Engine indices of the pinned particles, after a spatial sort.
  void find_pinned();
  // Puts the pinned particles where the container holds them at position_time, moving with
  // it at velocity_time; returns the largest squared displacement of one since the last
  // list build (0 without pinned particles).
  double pin(double position_time, double velocity_time);
  // Forces at the current positions (walls displaced to the current time, moving with
  // their velocity at velocity_time), then, if `finish`, the reactions gathered and the
  // half kick of length kick_dt (else the caller does both, fused with the next step).
  void evaluate_forces(double dt_history, double kick_dt, double velocity_time, bool finish);
  // The reactions gathered and the half kick of length dt, ending a step.
  void finish_step(double dt);
  // Throws BlowUp naming the deepest contact when the last force evaluation found one past
  // the overlap limit.
  void stop_if_too_deep() const;
  ForceContext force_context(double dt_history, double velocity_time);
  KickContext kick_context(double dt, bool keep_reactions = false);

  Model model_;
  WallSet walls_;
  Settings settings_;
  InstructionSet instruction_set_ = InstructionSet::Baseline;
  ThreadGovernor governor_;
  Kernels kernels_;
  Particles p_;
  NeighborList list_;
  Vectors spin_sum_;
  std::vector<LoopMaterial> pair_material_, wall_material_;
  // Wall geometry for the force loop, refreshed each step.
  std::vector<int> plane_axis_;
  std::vector<double> plane_sign_, plane_position_;
  std::vector<double*> wall_history_ptr_, wall_rolling_history_ptr_, normal_record_ptr_,
      tangential_record_ptr_;
  std::vector<Vectors> wall_normal_, wall_tangential_;
  struct Pinned {
    Eigen::Vector3d rest;  // position with the walls at rest
    int index;             // engine index, refreshed at every rebuild
  };
  std::vector<Pinned> pinned_;
  std::vector<std::int32_t> pinned_slot_;  // per tag: its place in pinned_, or -1
  bool recording_ = false;
  // The last step recorded contacts, whose forces its reaction slots still hold (read by
  // the frame); cleared before the next force pass.
  bool reactions_kept_ = false;
  double beyond_limit_ = 0.0;  // of the last force evaluation (see Kernels::forces)
  StepProfile profile_;
  std::int64_t step_ = 0, recorded_step_ = -1;
};

}  // namespace granpipe::dem
