#include "dem_source.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include "diagnostics.hpp"
#include "frame_output.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/step_count.hpp"
#include "granpipe/stop_request.hpp"
#include "kernels.hpp"
#include "scene_checks.hpp"
#include "start.hpp"
#include "start_checks.hpp"
#include "time_step.hpp"

namespace granpipe::dem {

namespace {

// Defaults: the reference runs of the Brazil-nut scene (../shared/bench/bnp), which give
// Table I's restitution 0.9 between small spheres.
constexpr double kKn = 2e5, kGammaN = 42.398;

Schema material_fields() {
  Schema m;
  m.real("k_n", kKn, "normal stiffness").min(0.0, true).unit("force/length");
  m.real("k_t", 2.0 / 7.0 * kKn, "tangential stiffness").min(0.0).unit("force/length");
  m.real("gamma_n", kGammaN, "normal damping rate, times m_eff (Table I)").min(0.0).unit("1/time");
  m.real("gamma_t", kGammaN / 2, "tangential damping rate, times m_eff").min(0.0).unit("1/time");
  m.real("mu", 0.5, "Coulomb friction coefficient").min(0.0);
  m.real("rolling_friction", 0.0,
         "rolling friction coefficient mu_r: a torque against rolling and twisting up to mu_r "
         "R_eff |F_n| (elastic-plastic spring of stiffness k_t R_eff^2); 0: none")
      .min(0.0);
  return m;
}

ContactMaterial material(const Params& p) {
  return {p.real("k_n"),     p.real("k_t"), p.real("gamma_n"),
          p.real("gamma_t"), p.real("mu"),  p.real("rolling_friction")};
}

Model model_of(const Params& p) {
  const SpeciesTable& species = p.species("species");
  const PairTable& pairs = p.pairs("contacts");
  Model m;
  m.density = species.reals("density");
  const int s = m.species();
  m.pair.resize(static_cast<std::size_t>(s * s));
  m.wall.resize(static_cast<std::size_t>(kWallCount * s));
  for (int a = 0; a < s; ++a) {
    m.fixed.push_back(species[static_cast<std::size_t>(a)].boolean("fixed"));
    for (int b = a; b < s; ++b) m.set_pair(a, b, material(pairs.at(a, b)));
    m.set_walls(a, material(p.object("walls")));
  }
  return m;
}

Drive drive_of(const Params& p) {
  const Params& d = p.object("drive");
  Drive drive;
  drive.form = d.choice<Drive::Form>("form");
  drive.amplitude = d.real("amplitude");
  drive.angular_frequency = 2.0 * std::numbers::pi * d.real("frequency");
  drive.start = d.real("start");
  if (d.integer("periods") > 0 && d.real("frequency") > 0.0) {
    drive.stop = drive.start + static_cast<double>(d.integer("periods")) / d.real("frequency");
  }
  return drive;
}

Settings settings_of(const PluginContext& ctx) {
  const Params& p = ctx.params;
  Settings s;
  s.dt = p.real("dt");
  const auto& g = p.reals("gravity");
  s.gravity = Eigen::Vector3d(g[0], g[1], g[2]);
  s.law = p.choice<ContactLaw>("law");
  s.friction = p.boolean("friction");
  s.rotation = p.boolean("rotation");
  s.skin = p.real("skin");
  s.background_damping = p.real("background_damping");
  s.air_damping = p.real("air_damping");
  s.threads = ctx.threads;
  s.adapt_threads = p.boolean("adapt_threads");
  // Resolved here, so that a path this processor lacks is refused naming the parameter.
  s.instruction_set =
      resolve(p.choice<InstructionSet>("instruction_set"), ctx.param("instruction_set"));
  return s;
}

// The fastest two particles of the start can approach each other at the sum of their
// speeds (one against a wall, at less).
double fastest_start_approach(const InitialState& s) {
  double first = 0.0, second = 0.0;
  for (Eigen::Index i = 0; i < s.velocity.cols(); ++i) {
    const double v = s.velocity.col(i).norm();
    if (v > first) {
      second = first;
      first = v;
    } else if (v > second) {
      second = v;
    }
  }
  return first + second;
}

// The fastest normal approach the scene can produce, for the Hertz contact time and the
// blow-up bound: the start's fastest approach, the walls' peak speed, and a free fall
// across the start (the particles and the walls around them, so that a sphere started
// above the base counts its drop). A scene where nothing moves gets a slow floor: the
// Hertz contact time needs a speed > 0.
double impact_speed(const Start& start, const Drive& drive, const Settings& s) {
  constexpr double kSlowest = 1e-3;
  double drop = 0.0;
  for (int a = 0; a < 3; ++a) {
    const auto x = start.state.position.row(a);
    if (x.size() == 0) continue;
    const auto& side = start.container.boundary[static_cast<std::size_t>(a)];
    const double lo =
        side[0] == Boundary::Wall ? std::min(x.minCoeff(), start.container.lo[a]) : x.minCoeff();
    const double hi =
        side[1] == Boundary::Wall ? std::max(x.maxCoeff(), start.container.hi[a]) : x.maxCoeff();
    drop = std::max(drop, hi - lo);
  }
  return std::max(kSlowest, fastest_start_approach(start.state) +
                                std::abs(drive.amplitude * drive.angular_frequency) +
                                std::sqrt(2.0 * s.gravity.stableNorm() * drop));
}

// The kinetic energy no sound run reaches: every particle ten times faster than the fastest
// approach the scene can produce, on top of its start velocity. A blow-up grows
// exponentially and passes it within a few steps; a sound bed stays far below it.
double kinetic_energy_bound(const InitialState& s, const Model& model, double speed) {
  double bound = 0.0;
  for (Eigen::Index i = 0; i < s.radius.size(); ++i) {
    const double v0 = s.velocity.cols() > 0 ? s.velocity.col(i).norm() : 0.0;
    const double v = 10.0 * speed + v0;
    bound += 0.5 * model.sphere_mass(s.species[i], s.radius[i]) * v * v;
  }
  return bound;
}

std::int64_t steps_in(double time, double dt) {
  return static_cast<std::int64_t>(std::ceil(time / dt - 1e-9));
}

// The run ends at the first step at or after the duration (less than a step late, as the
// frames' times show), but a duration shorter than one step ran a whole step (200 times
// 1e-6 with dt 2e-4) without a word.
void refuse_less_than_a_step(const PluginContext& ctx, double dt) {
  const double duration = ctx.params.real("duration");
  if (duration / dt >= 1.0 - 1e-9) return;
  std::ostringstream m;
  m << ctx.param("duration") << ": expected at least one time step (dt " << dt << "), got "
    << duration;
  throw InputError(m.str());
}

}  // namespace

Schema schema() {
  Schema s;
  s.path("initial_file", std::string(""),
         "frames file (H5MD) to start from: positions, radii, species, velocities if any, and "
         "the container, whose walls, base and cylinder become the engine's. Empty: start "
         "from a loose bed (bed)");
  s.integer("initial_frame", -1, "frame of initial_file to start from (-1: the last)").min(-1);
  Schema bed;
  bed.integer("small", 0,
              "spheres of species 0 on a loose lattice in a cylinder standing on z = 0 (stacked "
              "square layers, alternate layers shifted, nudged sideways at random); 0: start "
              "from initial_file; at most 5e6, about 10 GB (each sphere needs about 2 kB, "
              "and a bed this machine cannot hold is refused)")
      .range(0, 5e6);
  bed.real("diameter", 1.0, "the small spheres' diameter").min(0.0, true).unit("length");
  bed.real("intruder_diameter", 0.0,
           "diameter of an intruder (species 1) on the axis just above the base, the lattice "
           "built around it; 0: none")
      .min(0.0)
      .unit("length");
  bed.real("cylinder_diameter", 12.25, "inner diameter of the cylinder")
      .min(0.0, true)
      .unit("length");
  bed.real("spacing", 1.03, "distance between lattice neighbours, in small diameters")
      .min(1.0, true);
  bed.real("jitter", 0.01, "largest sideways nudge, in small diameters").min(0.0);
  s.object("bed", bed, "a generated start (instead of initial_file); the seed is the pipeline's");
  Schema species;
  // Any unit system's densities lie within the range; far outside it the masses, and with
  // them the contact times, leave the range of doubles.
  species.real("density", 1.91, "mass per unit volume").range(1e-20, 1e20).unit("mass/length^3");
  species.boolean("fixed", false,
                  "held by the container: moves rigidly with it (the paper's preparation fixes "
                  "the large sphere at the bottom)");
  s.species_table("species", species, R"([{"name": "small", "density": 1.91}])",
                  "the species of the start, by index");
  s.pair_table("contacts", "species", material_fields(), R"({"*": {}})",
               "particle-particle contact material per species pair");
  s.object("walls", material_fields(), "the walls' contact material (every wall, every species)");
  // Without a frequency the container stands still: an amplitude, start or number of
  // periods then does nothing (periods 5 would not end the run), and is refused.
  const auto moving = [](const Params& d) { return d.real("frequency") > 0.0; };
  Schema drive;
  drive.choice<Drive::Form>("form", Drive::Form::OneMinusCos,
                            "container motion z = A sin(wt), or A (1 - cos wt) from rest");
  drive.real("amplitude", 0.0, "A").unit("length").only_where("frequency > 0", moving);
  drive.real("frequency", 0.0, "f = w / 2 pi").min(0.0).unit("1/time");
  drive.real("start", 0.0, "time the motion starts")
      .min(0.0)
      .unit("time")
      .only_where("frequency > 0", moving);
  drive
      .integer("periods", 0,
               "the motion stops after this many periods, the container then at rest (where "
               "it started, for one_minus_cos); 0: never")
      .min(0)
      .only_where("frequency > 0", moving);
  s.object("drive", drive, "vibration of the whole container (base, cylinder and walls)");
  s.choice<ContactLaw>("law", ContactLaw::Linear, "contact law: linear spring-dashpot or Hertz");
  s.boolean("friction", true, "tangential forces with history and Coulomb's cap");
  s.boolean("rotation", true, "angular velocities and torques");
  s.real("dt", 2e-4, "time step (checked against the shortest contact time)")
      .min(0.0, true)
      .unit("time");
  s.real("duration", 1.0, "simulated time").min(0.0, true).unit("time");
  s.integer("save_every", 5000, "steps between emitted frames").min(1);
  s.real("save_from", 0.0,
         "frames are emitted at the multiples of save_every from this time on, and at the end "
         "of the duration (none is built before it; 0 emits the initial state too); a run "
         "that relaxes earlier (relaxed_kinetic_energy) still ends with its relaxed frame")
      .min(0.0)
      .unit("time");
  // Beyond a couple of diameters the lists hold hundreds of pairs a sphere, which the
  // memory estimate of about 2 kB a sphere does not cover (1e12 took gigabytes).
  s.real("skin", 0.2, "neighbour-list skin, in smallest diameters, at most 2")
      .min(0.0, true)
      .max(2.0);
  s.boolean("adapt_threads", true,
            "run on one thread while that is measured to be faster than all (a busy machine); "
            "false: always all");
  s.choice<InstructionSet>("instruction_set", InstructionSet::Auto,
                           "the force loops' vector instructions: auto takes the widest this "
                           "processor runs (or GRANPIPE_DEM_INSTRUCTION_SET's); the paths "
                           "differ in the last bits only");
  s.real("background_damping", 0.0, "b of the force -b v on every particle").min(0.0);
  s.real("air_damping", 0.0,
         "b_air of the interstitial air's drag -b_air (v - V), V the container's velocity "
         "(the paper's 1e-3 to 1e-2)")
      .min(0.0);
  s.reals("gravity", std::vector<double>{0.0, 0.0, -1.0}, "gravitational acceleration").length(3);
  s.real("relaxed_kinetic_energy", 0.0,
         "once the container is at rest, the run ends with a frame at the first check (at every "
         "multiple of 1000 steps) where the mean kinetic energy per particle (translational and "
         "rotational) "
         "is below this; 0: run the whole duration")
      .min(0.0)
      .unit("energy");
  return s;
}

DemSource::DemSource(const PluginContext& ctx) : log_(ctx.log), progress_(ctx.progress) {
  const Model model = model_of(ctx.params);
  const Start start = start_of(ctx, model.species());
  const Settings settings = settings_of(ctx);
  const Drive drive = drive_of(ctx.params);
  const WallSet walls(start.container, drive);
  const Scene scene{model, walls, start.state, settings.law};
  check_gravity(ctx, scene, settings.gravity);
  check_drive(ctx, scene, drive, settings.dt);
  if (!start.where.empty()) {
    check_start_motion(start.container, drive, settings.dt, start.state.radius.minCoeff(),
                       start.where);
    check_start_speeds(start.state, start.id, settings.dt, start.where);
    check_fixed_held(start.state, start.id, model,
                     {start.container.wall_velocity, drive.velocity(0.0)}, settings.dt,
                     start.where);
  }
  check_damping(ctx, scene, settings.background_damping, settings.air_damping, settings.dt);
  const double speed = impact_speed(start, drive, settings);
  check_dt(ctx, smallest_contact_time(model, walls, start.state.radius, start.state.species,
                                      settings.law, speed));
  read_schedule(ctx, drive);
  engine_ = std::make_unique<Engine>(model, walls, settings, start.state);
  ids_ = start.id;
  // The start's overlaps may all spring apart: their energy (a bed pressed 1 % deep releases
  // far more than its speeds) was called a blow-up.
  kinetic_energy_bound_ =
      kinetic_energy_bound(start.state, model, speed) + energy(*engine_).normal_elastic;
  engine_->record_contacts(true);
  timing_ = ctx.stream_table(
      "timing", Table({"step", "steps", "seconds", "particle_steps_per_second", "force_seconds",
                       "integrate_seconds", "neighbour_seconds", "rebuilds"},
                      "wall-clock time of each interval between emitted frames, and where it "
                      "went: pair and wall forces (one fused loop), integration, neighbour "
                      "lists"));
}

void DemSource::check_dt(const PluginContext& ctx, const ContactTime& shortest) {
  const StepCheck verdict = check_time_step(ctx.params.real("dt"), shortest);
  if (verdict.verdict == StepVerdict::Refuse)
    throw InputError(ctx.param("dt") + ": " + verdict.message);
  if (verdict.verdict == StepVerdict::Warn) log_.warn(ctx.param("dt") + ": " + verdict.message);
}

void DemSource::read_schedule(const PluginContext& ctx, const Drive& drive) {
  const Params& p = ctx.params;
  const double dt = p.real("dt");
  // Steps are counted in 64-bit integers: a duration of 1e300 wrapped round to a negative
  // count, refused as a save_from past it.
  check_step_count(p.real("duration") / dt, ctx.param("duration"), "time steps",
                   "duration / dt, dt " + format_number(dt));
  total_steps_ = end_step_ = steps_in(p.real("duration"), dt);
  refuse_less_than_a_step(ctx, dt);
  save_every_ = p.integer("save_every");
  // Compared as times first: a save_from of 1e16 wrapped round to a negative step.
  const bool within = p.real("save_from") <= p.real("duration");
  first_saved_step_ = within ? steps_in(p.real("save_from"), dt) : total_steps_ + 1;
  if (first_saved_step_ > total_steps_) {
    std::ostringstream m;
    m << ctx.param("save_from") << ": expected a time within the duration (" << p.real("duration")
      << "), got " << p.real("save_from");
    throw InputError(m.str());
  }
  relaxed_kinetic_energy_ = p.real("relaxed_kinetic_energy");
  if (relaxed_kinetic_energy_ > 0.0 && !drive.stopped(std::numeric_limits<double>::max())) {
    log_.warn(ctx.param("relaxed_kinetic_energy") +
              ": the container never stops (drive.periods is 0), so the run never ends early");
  }
}

FrameContent DemSource::content() const {
  FrameContent c{.dim = 3, .contacts = true};
  for (const char* name : {"velocity", "angular_velocity"}) {
    c.columns.push_back(*find_standard(name, Scope::Particle));
  }
  for (const char* name : {"overlap", "normal_force", "tangential_force", "point"}) {
    c.columns.push_back(*find_standard(name, Scope::Contact));
  }
  return c;
}

Source::Work DemSource::work() const { return {static_cast<double>(total_steps_), "steps", true}; }

std::int64_t DemSource::next_frame_step() const {
  const std::int64_t now = engine_->step();
  if (started_ && now >= end_step_) return -1;
  const std::int64_t due = std::max(started_ ? now + 1 : now, first_saved_step_);
  // The next multiple of save_every, counted from `due` up: rounding `due` up through
  // due + save_every - 1 overflowed for a save_every near 2^63 (frames of step 0 for ever).
  const std::int64_t rest = due % save_every_;
  if (rest == 0) return std::min(due, end_step_);
  return save_every_ - rest >= end_step_ - due ? end_step_ : due + (save_every_ - rest);
}

bool DemSource::next(Frame& frame) {
  const std::int64_t due = next_frame_step();
  if (due < 0) return false;
  if (!started_) {
    // Speeds depend on the instruction set (docs/benchmarks.md): the log says which ran.
    log_.info(std::string("dem: force loops for ") + label_of(engine_->instruction_set()) + ", " +
              std::to_string(engine_->particles().size()) + " particles, " +
              std::to_string(engine_->settings().threads) + " thread(s)");
  }
  started_ = true;
  run_to(due);
  fill_frame(*engine_, frame);
  frame.id() = ids_;
  return true;
}

bool DemSource::at_rest() const {
  if (relaxed_kinetic_energy_ <= 0.0 || !engine_->walls().drive().stopped(engine_->time())) {
    return false;
  }
  return kinetic_energy(engine_->particles()) <
         relaxed_kinetic_energy_ * engine_->particles().size();
}

void DemSource::run_to(std::int64_t step) {
  // Chunks end at multiples of this: short enough for a live progress bar, long enough to
  // cost nothing, and where relaxation is checked (also at a frame on such a step: runs
  // whose frames came every 1000 steps or less never checked it).
  constexpr std::int64_t kCheckEvery = 1000;
  using Clock = std::chrono::steady_clock;
  const StepProfile before = engine_->profile();
  const std::int64_t first = engine_->step();
  const auto start = Clock::now();
  while (engine_->step() < step) {
    throw_if_stop_requested();  // frames far apart: a signal is not left waiting for one
    const auto chunk_start = Clock::now();
    const std::int64_t steps =
        std::min(kCheckEvery - engine_->step() % kCheckEvery, step - engine_->step());
    // The wall forces a frame shows are kept only in the step before it: recording them
    // every step would store two vectors per particle and wall for nothing.
    const bool frame_follows = engine_->step() + steps == step;
    engine_->record_contacts(false);
    engine_->run(frame_follows ? steps - 1 : steps);
    if (frame_follows) {
      engine_->record_contacts(true);
      engine_->run(1);
    }
    check_health(*engine_, kinetic_energy_bound_);
    if (!relaxed_ && engine_->step() % kCheckEvery == 0 && at_rest()) {
      // Between frames one more step, so that the last frame shows the wall contacts too.
      relaxed_ = true;
      const bool frame_now = engine_->step() == step;
      end_step_ = step = frame_now ? step : engine_->step() + 1;
      std::ostringstream m;
      m << "dem: relaxed at t = " << engine_->time() << ": mean kinetic energy per particle below "
        << relaxed_kinetic_energy_ << "; the run ends with " << (frame_now ? "this" : "the next")
        << " step's frame";
      log_.info(m.str());
    }
    report_progress(steps, std::chrono::duration<double>(Clock::now() - chunk_start).count());
  }
  if (engine_->step() > first) {
    record_timing(engine_->step() - first,
                  std::chrono::duration<double>(Clock::now() - start).count(), before);
  }
}

void DemSource::report_progress(std::int64_t steps, double seconds) {
  const double t = engine_->time();
  const double rate = static_cast<double>(steps) * engine_->particles().size() / seconds;
  char status[160];
  const Drive& drive = engine_->walls().drive();
  if (drive.angular_frequency > 0.0) {
    std::snprintf(status, sizeof status, "t = %.2f, cycle %.2f, %.3g particle-steps/s", t,
                  drive.cycles(t), rate);
  } else {
    std::snprintf(status, sizeof status, "t = %.2f, %.3g particle-steps/s", t, rate);
  }
  progress_.set_status(status);
  progress_.advance(static_cast<double>(steps));
}

void DemSource::record_timing(std::int64_t steps, double seconds, const StepProfile& before) {
  const StepProfile& now = engine_->profile();
  const double particle_steps = static_cast<double>(steps) * engine_->particles().size();
  timing_.add_row({static_cast<double>(engine_->step()), static_cast<double>(steps), seconds,
                   particle_steps / seconds, now.forces - before.forces,
                   now.integrate - before.integrate, now.neighbour - before.neighbour,
                   static_cast<double>(now.rebuilds - before.rebuilds)});
}

void DemSource::finish(Results& results) {
  if (relaxed_kinetic_energy_ > 0.0 && !relaxed_) {
    std::ostringstream m;
    m << "dem: relaxed_kinetic_energy: not reached within the duration (mean kinetic energy "
      << kinetic_energy(engine_->particles()) / engine_->particles().size()
      << " per particle at t = " << engine_->time() << ")";
    log_.warn(m.str());
  }
  results.add_table("timing", timing_.table());
  const StepProfile& p = engine_->profile();
  if (p.steps_on_fewer_threads > 0) {
    std::ostringstream m;
    m << "dem: " << p.steps_on_fewer_threads << " of " << engine_->step()
      << " steps ran on 1 thread, measured faster than " << engine_->settings().threads
      << " while the machine was busy";
    log_.info(m.str());
  }
  const double particle_steps = static_cast<double>(engine_->step()) * engine_->particles().size();
  const double seconds = p.forces + p.integrate + p.neighbour;
  results.add_scalar("particle_steps_per_second", seconds > 0 ? particle_steps / seconds : 0.0,
                     std::nan(""), "1/s", "particle-steps per second of the time-stepping loops");
  // The pipeline records instruction_set "auto": which path ran is told here (its last bits
  // differ from another path's, so the same seed gives the same bits only on the same path).
  results.add_scalar("force_loop_width", doubles_per_vector(engine_->instruction_set()),
                     std::nan(""), "",
                     "the force loops' instruction-set path that ran, in doubles per vector: 2 "
                     "baseline, 4 AVX2, 8 AVX-512 (the paths differ in the last bits)");
}

}  // namespace granpipe::dem
