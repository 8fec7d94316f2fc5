#pragma once
// The rigid motion of the container: every wall is displaced by the same offset D(t)
// along `direction` (the container vibrates as one body),
//   Sine:          D(t) = A sin(w t),        V(t) = A w cos(w t)
//   OneMinusCos:   D(t) = A (1 - cos(w t)),  V(t) = A w sin(w t)   (LAMMPS' wiggle: from rest)
// with t counted from `start` (walls at rest before it) until `stop`, after which the walls
// rest where the motion left them (the paper's preparation terminates its vibration; with
// OneMinusCos over whole periods they rest where they started, without a jump in speed).
#include <Eigen/Core>
#include <limits>

namespace granpipe::dem {

struct Drive {
  enum class Form { Sine, OneMinusCos };
  Form form = Form::OneMinusCos;
  double amplitude = 0.0;                                // A (length)
  double angular_frequency = 0.0;                        // w = 2 pi f (1/time)
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit vector
  double start = 0.0;
  double stop = std::numeric_limits<double>::infinity();

  Eigen::Vector3d offset(double t) const;
  Eigen::Vector3d velocity(double t) const;
  // Drive periods since the motion started, (t - start) f; 0 before it, fixed after stop.
  double cycles(double t) const;
  bool moves() const { return amplitude != 0.0 && angular_frequency != 0.0; }
  // True from the stop on, and always for a container that never moves.
  bool stopped(double t) const { return !moves() || t >= stop; }
  // Throws InputError on a NaN/infinite amplitude, frequency or start, a NaN stop or one
  // before the start, or a direction that is not a unit vector.
  void check() const;
};

}  // namespace granpipe::dem
