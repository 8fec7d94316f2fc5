// Tests of the dem engine against analytic answers: head-on collisions (restitution and
// contact time of Eqs. 9-10, Hertz contact time), energy conservation, friction on an
// incline and the Coulomb cap, rest on the base, walls and their motion, contact history
// across neighbour-list rebuilds, thread-count independence, time-step safety, blow-up
// detection and the emitted frame.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "diagnostics.hpp"
#include "engine.hpp"
#include "frame_output.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/frame.hpp"
#include "loose_lattice.hpp"
#include "time_step.hpp"

namespace dem = granpipe::dem;
using granpipe::Boundary;
using granpipe::Container;
using granpipe::ContainerShape;
using granpipe::Frame;
using granpipe::InputError;
using granpipe::Wall;
using Eigen::Vector3d;
namespace partner = granpipe::partner;

namespace {

constexpr double kUnitMassDensity = 6.0 / std::numbers::pi;  // a sphere of diameter 1 weighs 1
constexpr double kKn = 2e5;

dem::ContactMaterial material(double kn, double gamma_n, double mu) {
  return {kn, 2.0 / 7.0 * kn, gamma_n, 0.5 * gamma_n, mu};
}

dem::Model one_species(const dem::ContactMaterial& m) {
  return dem::Model::uniform(1, kUnitMassDensity, m, m);
}

Container no_walls() {
  Container c;
  for (auto& axis : c.boundary) axis = {Boundary::Open, Boundary::Open};
  return c;
}

// A closed box [lo, hi]^3.
Container box(double lo, double hi) {
  Container c;
  c.lo = Vector3d::Constant(lo);
  c.hi = Vector3d::Constant(hi);
  return c;
}

// A flat base at z = 0, open elsewhere.
Container base_only() {
  Container c = no_walls();
  c.boundary[2][0] = Boundary::Wall;
  return c;
}

// A cylinder of this radius on a base at z = 0, open top.
Container cylinder(double radius) {
  Container c = base_only();
  c.shape = ContainerShape::Cylinder;
  c.cylinder_radius = radius;
  return c;
}

dem::InitialState spheres(const std::vector<Vector3d>& x, const std::vector<Vector3d>& v,
                          double radius = 0.5) {
  dem::InitialState s;
  const auto n = static_cast<Eigen::Index>(x.size());
  s.position.resize(3, n);
  s.velocity.resize(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    s.position.col(k) = x[static_cast<std::size_t>(k)];
    s.velocity.col(k) = v.empty() ? Vector3d::Zero() : v[static_cast<std::size_t>(k)];
  }
  s.radius = Eigen::ArrayXd::Constant(n, radius);
  s.species = Eigen::ArrayXi::Zero(n);
  return s;
}

dem::Settings settings(double dt, const Vector3d& gravity = Vector3d::Zero()) {
  dem::Settings s;
  s.dt = dt;
  s.gravity = gravity;
  return s;
}

Vector3d position(const dem::Engine& e, int tag) { return e.particles().x.col(e.index_of(tag)); }
Vector3d velocity(const dem::Engine& e, int tag) { return e.particles().v.col(e.index_of(tag)); }
Vector3d spin(const dem::Engine& e, int tag) { return e.particles().omega.col(e.index_of(tag)); }

// Time at which f (sampled at steps) crosses zero between t0 (f0) and t1 (f1).
double crossing(double t0, double f0, double t1, double f1) { return t0 + (t1 - t0) * f0 / (f0 - f1); }

struct Collision {
  double contact_time, restitution;
};

// Two unit spheres approaching head on at relative speed 1 along x; the contact time from
// the overlap's zero crossings, the restitution from the velocities after.
Collision head_on(const dem::Model& model, dem::Settings s) {
  dem::Engine e(model, dem::WallSet(no_walls(), {}), s,
                spheres({{0, 0, 0}, {1.001, 0, 0}}, {{0.5, 0, 0}, {-0.5, 0, 0}}));
  const auto overlap = [&] { return 1.0 - (position(e, 1) - position(e, 0)).norm(); };
  double previous = overlap(), start = -1, end = -1;
  while (end < 0) {
    e.run(1);
    const double now = overlap();
    if (previous <= 0 && now > 0) start = crossing(e.time() - s.dt, previous, e.time(), now);
    if (previous > 0 && now <= 0) end = crossing(e.time() - s.dt, previous, e.time(), now);
    previous = now;
  }
  e.run(10);  // clear of the contact
  return {end - start, (velocity(e, 1) - velocity(e, 0)).x() / 1.0};
}

}  // namespace

TEST(DemCollision, LinearHeadOnGivesRestitutionAndContactTimeOfEqs9And10) {
  const double gamma = dem::damping_for_restitution(0.9, kKn, 0.5);
  const double tc = dem::linear_contact_time(kKn, gamma, 0.5);
  EXPECT_NEAR(gamma, 42.398, 1e-3);  // the LAMMPS reference input's value
  EXPECT_NEAR(dem::linear_restitution(kKn, gamma, 0.5), 0.9, 1e-12);
  for (bool friction : {false, true}) {
    dem::Settings s = settings(tc / 50);
    s.friction = friction;
    const Collision c = head_on(one_species(material(kKn, gamma, 0.5)), s);
    EXPECT_NEAR(c.contact_time / tc, 1.0, 0.005) << "friction " << friction;
    EXPECT_NEAR(c.restitution / 0.9, 1.0, 0.005) << "friction " << friction;
  }
}

TEST(DemCollision, HertzHeadOnLastsTheAnalyticHertzContactTime) {
  const double tc = dem::hertz_contact_time(kKn, 1.0, 0.5, 1.0);
  dem::Settings s = settings(tc / 100);
  s.law = dem::ContactLaw::Hertz;
  const Collision c = head_on(one_species(material(kKn, 0.0, 0.5)), s);
  EXPECT_NEAR(c.contact_time / tc, 1.0, 0.01);
  EXPECT_NEAR(c.restitution, 1.0, 1e-3);
}
