#include "start_checks.hpp"

#include <limits>
#include <sstream>

#include "granpipe/deepest_overlap.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/particles_outside.hpp"
#include "overlap_limit.hpp"

namespace granpipe::dem {

namespace {

// What a saved start's walls and held particles may differ by from where the run puts them:
// rounding, 1e-9 of a length (the smallest radius) or of a speed (that length a step).
constexpr double kRounding = 1e-9;

std::string percent(double fraction) { return format_number(100.0 * fraction, 3) + " %"; }

std::string particle(const Frame& f, Eigen::Index i) {
  std::ostringstream s;  // "particle " + ... gave GCC 12 a false -Wrestrict
  s << "particle " << i << " (id " << f.id()[i] << ") at " << format_point(f.position().row(i));
  return s.str();
}

void refuse_outside(const Frame& f, const std::string& where) {
  // An open side holds nothing back (a bed saved in flight may be above its container's top).
  Frame stated = f;
  Container& c = stated.container;
  c.wall_offset.setZero();  // the start's walls go where the drive puts them at t = 0
  for (int axis = 0; axis < 3; ++axis) {
    if (c.boundary[axis][0] == Boundary::Open)
      c.lo[axis] = -std::numeric_limits<double>::infinity();
    if (c.boundary[axis][1] == Boundary::Open) c.hi[axis] = std::numeric_limits<double>::infinity();
  }
  const auto out = first_particle_outside(stated, kMaxOverlapFraction);
  if (!out) return;
  throw InputError(
      where + ": " + particle(f, out->particle) + " reaches " + format_number(out->depth) +
      " past wall " + to_string(out->wall) + " (" +
      percent(out->depth / f.radius()[out->particle]) +
      " of its radius): expected particles inside the container, touching its walls by "
      "at most " +
      percent(kMaxOverlapFraction) + " of their radius");
}

void refuse_deep_pairs(const Frame& f, const std::string& where) {
  const auto deepest = deepest_pair_overlap(f, where);
  if (!deepest || deepest->fraction <= kMaxOverlapFraction) return;
  const auto i = deepest->i, j = deepest->j;
  throw InputError(where + ": particles " + std::to_string(i) + " and " + std::to_string(j) +
                   " (ids " + std::to_string(f.id()[i]) + " and " + std::to_string(f.id()[j]) +
                   ") overlap by " + percent(deepest->fraction) +
                   " of the smaller radius: expected overlaps of at most " +
                   percent(kMaxOverlapFraction));
}

}  // namespace

void check_start_frame(const Frame& f, const std::string& where) {
  if (f.size() == 0) throw InputError(where + ": expected at least one particle, got none");
  refuse_outside(f, where);
  refuse_deep_pairs(f, where);
}

// A frame saved mid-cycle (bnp_t10.h5, its base 9.1 up and rising) was put back at rest
// without a word, its bed then 9.1 above the base and falling. A container at rest starts
// any drive (a sine drive's walls then set off at A w); one moving must move as the drive
// does at t = 0 (a sine run's first frame). A stopped sine drive leaves A sin(2 pi n),
// 1e-18 and not 0, which is rounding: within 1e-9 of the smallest radius, and of that
// length a step for the velocity.
void check_start_motion(const Container& c, const Drive& drive, double dt, double radius,
                        const std::string& where) {
  const Eigen::Vector3d offset = drive.offset(0.0), velocity = drive.velocity(0.0);
  const double speed_rounding = kRounding * (velocity.norm() + radius / dt);
  const bool placed = (c.wall_offset - offset).norm() <= kRounding * radius;
  const bool moving = c.wall_velocity.norm() <= speed_rounding ||
                      (c.wall_velocity - velocity).norm() <= speed_rounding;
  if (placed && moving) return;
  throw InputError(where + ": expected its walls where the drive puts them at t = 0 (offset " +
                   format_point(offset) + ", velocity " + format_point(velocity) +
                   "; the run starts them there and its clock at 0), got offset " +
                   format_point(c.wall_offset) + " and velocity " + format_point(c.wall_velocity));
}

void check_start_speeds(const InitialState& start, const IndexArray& id, double dt,
                        const std::string& where) {
  for (Eigen::Index i = 0; i < start.velocity.cols(); ++i) {
    const double speed = start.velocity.col(i).stableNorm();  // norm() squared 1e200 to inf
    const double most = kMaxOverlapFraction * start.radius[i] / dt;
    if (speed <= most) continue;  // NaN was refused by the reader
    std::ostringstream s;
    s << where << ": particle " << i << " (id " << id[i] << ") moves at " << format_number(speed, 3)
      << ", " << format_number(speed * dt, 3) << " a step of dt = " << format_number(dt) << " ("
      << percent(speed * dt / start.radius[i])
      << " of its radius): expected speeds <= " << format_number(most, 3) << " ("
      << percent(kMaxOverlapFraction) << " of the radius a step; a longer step cannot resolve "
      << "its contacts)";
    throw InputError(s.str());
  }
}

void check_fixed_held(const InitialState& start, const IndexArray& id, const Model& model,
                      const std::array<Eigen::Vector3d, 2>& held_velocities, double dt,
                      const std::string& where) {
  // A start without velocities or angular velocities (a file of another code) has none.
  const auto column = [](const Vectors& v, Eigen::Index i) {
    return i < v.cols() ? Eigen::Vector3d(v.col(i)) : Eigen::Vector3d::Zero();
  };
  for (Eigen::Index i = 0; i < start.radius.size(); ++i) {
    if (!model.is_fixed(start.species[i])) continue;
    const double r = start.radius[i];
    const Eigen::Vector3d v = column(start.velocity, i), w = column(start.angular_velocity, i);
    const auto held = [&](const Eigen::Vector3d& u) {
      return (v - u).norm() <= kRounding * (u.norm() + r / dt);
    };
    const bool still = w.norm() * r <= kRounding * r / dt;
    if (still && (held(held_velocities[0]) || held(held_velocities[1]))) continue;
    std::ostringstream s;
    s << where << ": particle " << i << " (id " << id[i] << ") of fixed species "
      << start.species[i] << " moves at " << format_point(v) << ", spinning at " << format_point(w)
      << ": expected it held by the container, moving as the container does, at "
      << format_point(held_velocities[0]);
    if (held_velocities[1] != held_velocities[0])
      s << " (or setting off with the drive at " << format_point(held_velocities[1]) << ")";
    s << ", without spin";
    throw InputError(s.str());
  }
}

}  // namespace granpipe::dem
