#include "engine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "blow_up.hpp"
#include "deep_overlap.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/huge_pages.hpp"
#include "idle_cores.hpp"
#include "overlap_limit.hpp"

namespace granpipe::dem {

namespace {

[[noreturn]] void refuse(const std::string& what, const std::string& expected, double got) {
  std::ostringstream s;
  s << "dem: " << what << ": expected " << expected << ", got " << got;
  throw InputError(s.str());
}

void check_vectors(const Vectors& a, Eigen::Index n, const char* name, bool optional) {
  if (optional && a.cols() == 0) return;
  if (a.cols() != n) {
    refuse(std::string("initial ") + name, std::to_string(n) + " vectors (one per particle)",
           static_cast<double>(a.cols()));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(a(c, i))) {
        refuse("particle " + std::to_string(i) + ": " + name + " " + "xyz"[c], "a finite value",
               a(c, i));
      }
    }
  }
}

}  // namespace

void Settings::check() const {
  if (!(std::isfinite(dt) && dt > 0.0)) refuse("dt", "a finite time step > 0", dt);
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(gravity[a])) refuse("gravity", "a finite vector", gravity[a]);
  }
  if (!(std::isfinite(skin) && skin > 0.0)) {
    refuse("skin", "a finite value > 0 (in smallest diameters)", skin);
  }
  if (!(std::isfinite(background_damping) && background_damping >= 0.0)) {
    refuse("background damping", "a finite value >= 0", background_damping);
  }
  if (!(std::isfinite(air_damping) && air_damping >= 0.0)) {
    refuse("air damping", "a finite value >= 0", air_damping);
  }
  if (threads < 1) refuse("threads", "at least 1", threads);
}

Engine::Engine(const Model& model, const WallSet& walls, const Settings& settings,
               const InitialState& initial)
    : model_(model),
      walls_(walls),
      settings_(settings),
      governor_(std::max(settings.threads, 1), settings.adapt_threads,
                settings.adapt_threads ? idle_cores() : settings.threads) {
  settings_.check();
  model_.check();
  if (model_.rolls() && !(settings_.friction && settings_.rotation)) {
    throw InputError(
        "dem: rolling_friction: expected friction and rotation on (a rolling torque acts on "
        "rolling spheres), got rolling friction with " +
        std::string(settings_.friction ? "rotation" : "friction") + " off");
  }
  instruction_set_ = resolve(settings_.instruction_set, "dem: instruction_set");
  kernels_ = select_kernels(instruction_set_, settings_.law, settings_.friction, settings_.rotation,
                            model_.rolls());
  load_particles(initial);
  prepare_materials();
  const double smallest = p_.size() > 0 ? 2.0 * p_.radius.minCoeff() : 1.0;
  list_ = NeighborList(settings_.skin * smallest, kernels_.reaction_stride, settings_.friction,
                       model_.rolls());
  rebuild();
  refuse_coincident_centres();
  pin(time(), time());
  evaluate_forces(0.0, 0.0, time(), true);
}

void Engine::stop_if_too_deep() const {
  if (!(beyond_limit_ > 0.0)) return;
  const DeepOverlap d = deepest_overlap(p_, list_, walls_, wall_offset());
  std::ostringstream s;
  s << "dem: step " << step_ << " (t = " << time() << "): " << describe(d)
    << ": the contacts are too soft for the speed of impact, or dt too long; raise k_n, "
       "lower the speeds or reduce dt (now "
    << settings_.dt << ")";
  throw BlowUp(s.str());
}

void Engine::refuse_coincident_centres() const {
  for (int i = 0; i < p_.size(); ++i) {
    for (std::int32_t k = list_.first[i]; k < list_.first[i + 1]; ++k) {
      const int j = list_.partner[k];
      if (p_.x.col(i) != p_.x.col(j)) continue;
      const auto [a, b] = std::minmax(p_.tag[i], p_.tag[j]);
      throw InputError("dem: particles " + std::to_string(a) + " and " + std::to_string(b) +
                       ": expected distinct centres, got the same position (no contact "
                       "normal exists)");
    }
  }
}

void Engine::load_particles(const InitialState& in) {
  const Eigen::Index n = in.radius.size();
  if (n > std::numeric_limits<std::int32_t>::max() / 8) {
    refuse("particles", "fewer than 2^28", static_cast<double>(n));
  }
  check_vectors(in.position, n, "position", false);
  check_vectors(in.velocity, n, "velocity", true);
  check_vectors(in.angular_velocity, n, "angular velocity", true);
  if (in.species.size() != n) {
    refuse("initial species", std::to_string(n) + " values (one per particle)",
           static_cast<double>(in.species.size()));
  }
  p_.x = in.position;
  p_.v = in.velocity.cols() == n ? in.velocity : Vectors::Zero(3, n);
  p_.omega = in.angular_velocity.cols() == n ? in.angular_velocity : Vectors::Zero(3, n);
  p_.force = p_.torque = spin_sum_ = Vectors::Zero(3, n);
  p_.radius = in.radius;
  p_.species = in.species;
  p_.inv_mass.resize(n);
  p_.inv_inertia.resize(n);
  p_.tag.resize(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const double a = in.radius[i];
    const int s = in.species[i];
    if (!(std::isfinite(a) && a > 0.0)) {
      refuse("particle " + std::to_string(i) + ": radius", "a finite value > 0", a);
    }
    if (s < 0 || s >= model_.species()) {
      refuse("particle " + std::to_string(i) + ": species",
             "a species in 0.." + std::to_string(model_.species() - 1), s);
    }
    const double mass = model_.sphere_mass(s, a);
    p_.inv_mass[i] = 1.0 / mass;
    p_.inv_inertia[i] = 1.0 / (0.4 * mass * a * a);
    p_.tag[i] = static_cast<std::int32_t>(i);
  }
  hold_fixed_species();
  if (settings_.friction) p_.wall_history.assign(walls_.count(), Vectors::Zero(3, n));
  if (model_.rolls()) p_.wall_rolling_history.assign(walls_.count(), Vectors::Zero(3, n));
  p_.prefer_huge_pages();
  huge_pages::advise(spin_sum_.data(), static_cast<std::size_t>(spin_sum_.size()) * sizeof(double));
}

void Engine::prepare_materials() {
  const int S = model_.species();
  pair_material_.clear();
  for (const ContactMaterial& m : model_.pair) pair_material_.push_back(loop_material(m));
  wall_material_.clear();
  for (int slot = 0; slot < walls_.count(); ++slot) {
    for (int s = 0; s < S; ++s) {
      wall_material_.push_back(loop_material(model_.with_wall(walls_.wall_of_slot(slot), s)));
    }
  }
  for (const PlaneWall& w : walls_.planes()) {
    plane_axis_.push_back(w.axis);
    plane_sign_.push_back(w.sign);
  }
  plane_position_.resize(walls_.planes().size());
  wall_history_ptr_.resize(p_.wall_history.size());
  wall_rolling_history_ptr_.resize(p_.wall_rolling_history.size());
}

void Engine::hold_fixed_species() {
  const Eigen::Vector3d offset = walls_.drive().offset(time());
  pinned_.clear();
  pinned_slot_.assign(p_.tag.size(), -1);
  for (int i = 0; i < p_.size(); ++i) {
    if (!model_.is_fixed(p_.species[i])) continue;
    pinned_slot_[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(pinned_.size());
    pinned_.push_back({p_.x.col(i) - offset, i});
  }
}

void Engine::rebuild() {
  list_.rebuild(p_, governor_.threads());
  find_pinned();
}

void Engine::find_pinned() {
  if (pinned_.empty()) return;
  for (int i = 0; i < p_.size(); ++i) {
    const std::int32_t slot =
        pinned_slot_[static_cast<std::size_t>(p_.tag[static_cast<std::size_t>(i)])];
    if (slot >= 0) pinned_[static_cast<std::size_t>(slot)].index = i;
  }
}

double Engine::pin(double position_time, double velocity_time) {
  if (pinned_.empty()) return 0.0;
  const Eigen::Vector3d offset = walls_.drive().offset(position_time);
  const Eigen::Vector3d velocity = walls_.drive().velocity(velocity_time);
  const Vectors& built = list_.positions_at_build();
  double moved = 0.0;
  for (const Pinned& q : pinned_) {
    p_.x.col(q.index) = q.rest + offset;
    p_.v.col(q.index) = velocity;
    p_.omega.col(q.index).setZero();
    moved = std::max(moved, (p_.x.col(q.index) - built.col(q.index)).squaredNorm());
  }
  return moved;
}

ForceContext Engine::force_context(double dt_history, double velocity_time) {
  const Eigen::Vector3d offset = walls_.drive().offset(time());
  for (std::size_t s = 0; s < plane_position_.size(); ++s) {
    plane_position_[s] = walls_.planes()[s].rest_position + offset[plane_axis_[s]];
  }
  for (std::size_t s = 0; s < wall_history_ptr_.size(); ++s) {
    wall_history_ptr_[s] = p_.wall_history[s].data();
  }
  for (std::size_t s = 0; s < wall_rolling_history_ptr_.size(); ++s) {
    wall_rolling_history_ptr_[s] = p_.wall_rolling_history[s].data();
  }
  ForceContext c;
  c.n = p_.size();
  c.x = p_.x.data();
  c.v = p_.v.data();
  c.omega = p_.omega.data();
  c.radius = p_.radius.data();
  c.inv_mass = p_.inv_mass.data();
  c.species = p_.species.data();
  c.species_count = model_.species();
  c.pair_material = pair_material_.data();
  c.planes = static_cast<int>(plane_position_.size());
  c.plane_axis = plane_axis_.data();
  c.plane_sign = plane_sign_.data();
  c.plane_position = plane_position_.data();
  c.cylinder = walls_.has_cylinder();
  c.cylinder_x = walls_.rest().cylinder_center[0] + offset[0];
  c.cylinder_y = walls_.rest().cylinder_center[1] + offset[1];
  c.cylinder_radius = walls_.rest().cylinder_radius;
  c.wall_material = wall_material_.data();
  c.wall_velocity = walls_.drive().velocity(velocity_time);
  c.wall_history = wall_history_ptr_.data();
  c.wall_rolling_history = wall_rolling_history_ptr_.data();
  c.wall_normal_record = recording_ ? normal_record_ptr_.data() : nullptr;
  c.wall_tangential_record = recording_ ? tangential_record_ptr_.data() : nullptr;
  c.first = list_.first.data();
  c.partner = list_.partner.data();
  c.owner = list_.owner.data();
  c.reaction_slot = list_.reaction_slot.data();
  c.work_before = list_.work_before.data();
  c.history = list_.history.data();
  c.rolling_history = list_.rolling_history.data();
  c.incoming = list_.incoming.data();
  c.background_damping = settings_.background_damping;
  c.air_damping = settings_.air_damping;
  c.dt_history = dt_history;
  c.overlap_limit = kMaxOverlapFraction;
  c.threads = governor_.threads();
  c.force = p_.force.data();
  c.spin_sum = spin_sum_.data();
  return c;
}

KickContext Engine::kick_context(double dt, bool keep_reactions) {
  KickContext c;
  c.keep_reactions = keep_reactions;
  c.n = p_.size();
  c.x = p_.x.data();
  c.v = p_.v.data();
  c.omega = p_.omega.data();
  c.force = p_.force.data();
  c.torque = p_.torque.data();
  c.radius = p_.radius.data();
  c.inv_mass = p_.inv_mass.data();
  c.inv_inertia = p_.inv_inertia.data();
  c.spin_sum = spin_sum_.data();
  c.x_build = list_.positions_at_build().data();
  c.incoming = list_.incoming.data();
  c.reverse_first = list_.reverse_first.data();
  c.gravity = settings_.gravity;
  c.dt = dt;
  c.threads = governor_.threads();
  return c;
}

void Engine::evaluate_forces(double dt_history, double kick_dt, double velocity_time, bool finish) {
  // The force pass writes only the touching pairs' slots: a frame's kept reactions go first.
  if (reactions_kept_) {
    std::fill(list_.incoming.begin(), list_.incoming.end(), 0.0);
    reactions_kept_ = false;
  }
  if (recording_) {
    for (int s = 0; s < walls_.count(); ++s) {
      wall_normal_[s].resize(3, p_.size());
      wall_tangential_[s].resize(3, p_.size());
      normal_record_ptr_[s] = wall_normal_[s].data();
      tangential_record_ptr_[s] = wall_tangential_[s].data();
    }
  }
  beyond_limit_ = kernels_.forces(force_context(dt_history, velocity_time));
  if (recording_) recorded_step_ = step_;
  if (finish) finish_step(kick_dt);
}

// The end of a step; the step a frame shows keeps its contacts' forces in the reaction
// slots for the frame.
void Engine::finish_step(double dt) {
  kernels_.finish_step(kick_context(dt, recording_));
  reactions_kept_ = recording_;
}

namespace {

// Wall-clock seconds since the previous lap (or since it was made).
class LapTimer {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }
  // The steady clock's reading at the last lap, in seconds.
  double seconds() const { return std::chrono::duration<double>(last_.time_since_epoch()).count(); }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

void Engine::run(std::int64_t steps) {
  if (steps <= 0) return;
  const double dt = settings_.dt;
  LapTimer timer;
  governor_.resume(timer.seconds());
  double moved = kernels_.start_step(kick_context(dt));
  moved = std::max(moved, pin(time() + dt, time() + 0.5 * dt));
  profile_.integrate += timer.lap();
  for (std::int64_t s = 0; s < steps; ++s) {
    ++step_;
    if (moved > list_.trigger_squared()) {
      rebuild();
      ++profile_.rebuilds;
      profile_.neighbour += timer.lap();
    }
    evaluate_forces(dt, dt, time() - 0.5 * dt, false);
    profile_.forces += timer.lap();
    // A step is timed from one force pass to the next (a run() may be a single step).
    if (governor_.threads() < settings_.threads) ++profile_.steps_on_fewer_threads;
    governor_.step_done(timer.seconds());
    // A contact past the limit ends the run with this step completed.
    if (s + 1 == steps || beyond_limit_ > 0.0) {
      finish_step(dt);
      pin(time(), time());
      profile_.integrate += timer.lap();
      stop_if_too_deep();
      return;
    }
    moved = kernels_.finish_and_start(kick_context(dt));
    moved = std::max(moved, pin(time() + dt, time() + 0.5 * dt));
    profile_.integrate += timer.lap();
  }
}

void Engine::release_contact_records() {
  for (Vectors& record : wall_normal_) record.resize(3, 0);
  for (Vectors& record : wall_tangential_) record.resize(3, 0);
  recorded_step_ = -1;
}

void Engine::record_contacts(bool on) {
  recording_ = on;
  if (!on) {
    // The records are as large as the particle arrays, and kept only for a frame.
    release_contact_records();
    return;
  }
  wall_normal_.resize(static_cast<std::size_t>(walls_.count()));
  wall_tangential_.resize(static_cast<std::size_t>(walls_.count()));
  normal_record_ptr_.resize(static_cast<std::size_t>(walls_.count()));
  tangential_record_ptr_.resize(static_cast<std::size_t>(walls_.count()));
  // At step 0 the forces were evaluated without advancing anything, so evaluating them
  // again gives the same forces, now recorded.
  if (step_ == 0) evaluate_forces(0.0, 0.0, time(), true);
}

void Engine::set_drive(const Drive& drive) { walls_.set_drive(drive); }

int Engine::index_of(std::int32_t tag) const {
  const auto it = std::find(p_.tag.begin(), p_.tag.end(), tag);
  return it == p_.tag.end() ? -1 : static_cast<int>(it - p_.tag.begin());
}

std::optional<Vec3> Engine::pair_history(std::int32_t tag_a, std::int32_t tag_b) const {
  const int a = index_of(tag_a), b = index_of(tag_b);
  if (!settings_.friction || a < 0 || b < 0) return std::nullopt;
  const auto find = [&](int owner, int other) -> std::optional<Vec3> {
    for (std::int32_t k = list_.first[owner]; k < list_.first[owner + 1]; ++k) {
      if (list_.partner[k] == other)
        return Vec3::Map(&list_.history[3 * static_cast<std::size_t>(k)]);
    }
    return std::nullopt;
  };
  if (auto u = find(a, b)) return u;
  if (auto u = find(b, a)) return Vec3(-*u);
  return std::nullopt;
}

std::optional<Vec3> Engine::wall_history(std::int32_t tag, Wall w) const {
  const int i = index_of(tag);
  if (!settings_.friction || i < 0) return std::nullopt;
  for (int slot = 0; slot < walls_.count(); ++slot) {
    if (walls_.wall_of_slot(slot) == w) return Vec3(p_.wall_history[slot].col(i));
  }
  return std::nullopt;
}

}  // namespace granpipe::dem
