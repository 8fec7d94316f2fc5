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

// Row k of a 3-component contact column.
Vector3d contact_vector(const Frame& f, const char* name, Eigen::Index k) {
  return f.contacts->get<granpipe::Coordinates>(name).row(k).matrix().transpose();
}

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

TEST(DemEnergy, ElasticSpheresInABoxKeepTheirEnergy) {
  // Ten spheres of diameter 0.5 bouncing in a closed box without damping or friction.
  dem::ContactMaterial m = material(kKn, 0.0, 0.0);
  dem::InitialState s = spheres({{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}, {2.5, 0.5, 0.5},
                                 {0.5, 1.5, 0.5}, {1.5, 1.5, 1.5}, {2.5, 2.5, 0.5},
                                 {0.5, 2.5, 2.5}, {1.5, 2.5, 1.5}, {2.5, 1.5, 2.5},
                                 {0.5, 0.5, 2.5}},
                                {{1, 0.3, -0.2}, {-0.5, 1, 0.1}, {0.2, -0.7, 1}, {-1, -1, 0.4},
                                 {0.6, 0.1, -1}, {0.9, -0.4, 0.3}, {-0.2, 0.8, -0.6},
                                 {0.4, 0.4, 0.9}, {-0.8, 0.2, -0.3}, {0.1, -0.9, 0.7}},
                                0.25);
  const double tc = dem::linear_contact_time(kKn, 0.0, 0.5 * std::pow(0.5, 3));
  dem::Settings st = settings(tc / 50);
  st.friction = false;
  dem::Engine e(one_species(m), dem::WallSet(box(0, 3), {}), st, s);
  const double e0 = dem::energy(e).total();
  double worst = 0.0;
  for (int k = 0; k < 100; ++k) {
    e.run(1000);
    worst = std::max(worst, std::abs(dem::energy(e).total() / e0 - 1.0));
  }
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(e.neighbors().builds(), 10);  // the spheres did move about
}

namespace {

// A sphere of unit mass resting on the base under gravity g tilted by theta about y, so
// that it feels the base as an incline; friction mu, no rotation (a sliding block).
dem::Engine on_incline(double theta, double mu) {
  dem::ContactMaterial m = material(kKn, dem::damping_for_restitution(0.5, kKn, 1.0), mu);
  const Vector3d g(std::sin(theta), 0.0, -std::cos(theta));
  dem::Settings s = settings(1e-4, g);
  s.rotation = false;
  const double rest = 0.5 - std::cos(theta) / kKn;  // the centre height at rest
  return dem::Engine(one_species(m), dem::WallSet(base_only(), {}), s,
                     spheres({{0, 0, rest}}, {}));
}

}  // namespace

TEST(DemFriction, SphereOnAnInclineSticksBelowTheFrictionAngle) {
  const double mu = 0.5, theta = std::atan(0.8 * mu);
  dem::Engine e = on_incline(theta, mu);
  e.run(20000);
  const double x1 = position(e, 0).x();
  e.run(20000);
  // The tangential spring holds it: it moves by its elastic stretch, m g sin(theta) / k_t
  // at most, then not at all.
  EXPECT_LT(std::abs(x1), 2.0 * std::sin(theta) / (2.0 / 7.0 * kKn));
  EXPECT_LT(std::abs(position(e, 0).x() - x1), 1e-12);
  EXPECT_LT(velocity(e, 0).norm(), 1e-9);
}

TEST(DemFriction, SphereOnASteeperInclineSlidesWithCoulombsAcceleration) {
  const double mu = 0.5, theta = std::atan(1.4 * mu);
  dem::Engine e = on_incline(theta, mu);
  e.run(2000);
  const double v1 = velocity(e, 0).x(), t1 = e.time();
  e.run(10000);
  const double a = (velocity(e, 0).x() - v1) / (e.time() - t1);
  EXPECT_NEAR(a / (std::sin(theta) - mu * std::cos(theta)), 1.0, 1e-6);
}

TEST(DemFriction, SlidingContactCarriesExactlyMuTimesTheNormalForce) {
  // A sphere launched along the base without spin slides until friction makes it roll
  // (after 2 v0 / (7 mu g)); until then |F_t| = mu |F_n| in the emitted contact table.
  const double mu = 0.3;
  dem::ContactMaterial m = material(kKn, dem::damping_for_restitution(0.5, kKn, 1.0), mu);
  dem::Engine e(one_species(m), dem::WallSet(base_only(), {}),
                settings(1e-4, -Vector3d::UnitZ()),
                spheres({{0, 0, 0.5 - 1.0 / kKn}}, {{1.0, 0, 0}}));
  e.record_contacts(true);
  const double rolling_from = 2.0 / (7.0 * mu);
  Frame f;
  int sliding = 0, rolling = 0;
  for (int k = 0; k < 40; ++k) {
    e.run(500);
    dem::fill_frame(e, f);
    ASSERT_EQ(f.contacts->rows(), 1);
    EXPECT_EQ(f.contact_i()[0], 0);
    EXPECT_EQ(f.contact_j()[0], partner::wall(Wall::ZLow));
    const Vector3d fn = contact_vector(f, "normal_force", 0);
    const Vector3d ft = contact_vector(f, "tangential_force", 0);
    const double ratio = ft.norm() / (mu * fn.norm());
    if (e.time() < 0.95 * rolling_from) {
      EXPECT_NEAR(ratio, 1.0, 1e-12) << "t = " << e.time();
      EXPECT_LT(ft.x(), 0.0);  // against the sliding
      ++sliding;
    } else if (e.time() > 1.05 * rolling_from) {
      EXPECT_LT(ratio, 1.0) << "t = " << e.time();
      ++rolling;
    }
  }
  EXPECT_GT(sliding, 5);
  EXPECT_GT(rolling, 5);
  // Rolling without slipping at 5/7 of the launch speed.
  EXPECT_NEAR(velocity(e, 0).x(), 5.0 / 7.0, 1e-3);
  EXPECT_NEAR(spin(e, 0).y() * 0.5, velocity(e, 0).x(), 1e-3);
}

TEST(DemWalls, SphereAtRestOnTheBasePressesItByItsWeightOverTheStiffness) {
  for (const dem::ContactLaw law : {dem::ContactLaw::Linear, dem::ContactLaw::Hertz}) {
    // Hertzian damping fades as sqrt(delta/d): it needs a larger coefficient to settle.
    dem::ContactMaterial m = material(kKn, law == dem::ContactLaw::Linear ? 40.0 : 5000.0, 0.5);
    dem::Settings s = settings(1e-4, -Vector3d::UnitZ());
    s.law = law;
    dem::Engine e(one_species(m), dem::WallSet(base_only(), {}), s, spheres({{0, 0, 0.5}}, {}));
    e.run(30000);
    const double overlap = 0.5 - position(e, 0).z();
    // m g = k_n delta (linear), = k_n delta^(3/2) / sqrt(d) with d = 2 R = 1 (Hertz).
    const double expected = law == dem::ContactLaw::Linear ? 1.0 / kKn : std::pow(1.0 / kKn, 2.0 / 3.0);
    EXPECT_NEAR(overlap / expected, 1.0, 1e-9) << static_cast<int>(law);
    EXPECT_LT(velocity(e, 0).norm(), 1e-12);
  }
}

TEST(DemWalls, SphereBouncingBetweenTwoWallsKeepsItsRestitution) {
  const double gamma = dem::damping_for_restitution(0.8, kKn, 1.0);
  const double e_wall = dem::linear_restitution(kKn, gamma, 1.0);  // m_eff = m at a wall
  ASSERT_NEAR(e_wall, 0.8, 1e-12);
  dem::ContactMaterial m = material(kKn, gamma, 0.5);
  Container c = no_walls();
  c.lo.z() = 0.0;
  c.hi.z() = 2.0;
  c.boundary[2] = {Boundary::Wall, Boundary::Wall};
  dem::Engine e(one_species(m), dem::WallSet(c, {}),
                settings(dem::linear_contact_time(kKn, gamma, 1.0) / 100),
                spheres({{0, 0, 1.0}}, {{0, 0, -1.0}}));
  double speed = 1.0, sign = -1.0;
  for (int bounce = 0; bounce < 4; ++bounce) {
    while (velocity(e, 0).z() * sign > 0) e.run(1);
    while (std::min(position(e, 0).z(), 2.0 - position(e, 0).z()) < 0.5) e.run(1);
    const double after = std::abs(velocity(e, 0).z());
    EXPECT_NEAR(after / speed / e_wall, 1.0, 0.005) << "bounce " << bounce;
    speed = after;
    sign = -sign;
  }
}

TEST(DemWalls, SphereWedgedBetweenCylinderAndBaseComesToRest) {
  // Gravity tilted by 30 degrees towards the side wall: the sphere rolls into the corner,
  // bounces and settles wedged between the two walls, pressed into the side by
  // m g sin(theta) and into the base by m g cos(theta), with friction and spin on.
  const double theta = std::numbers::pi / 6, a = 0.5, R = 2.0;
  const Vector3d g(std::sin(theta), 0.0, -std::cos(theta));
  dem::ContactMaterial m = material(kKn, dem::damping_for_restitution(0.3, kKn, 1.0), 0.5);
  dem::Engine e(one_species(m), dem::WallSet(cylinder(R), {}), settings(1e-4, g),
                spheres({{R - a - 0.01, 0, a - std::cos(theta) / kKn}}, {}));
  e.record_contacts(true);
  const double energy = dem::energy(e).total();
  for (int k = 0; k < 40; ++k) {
    e.run(1000);
    ASSERT_LE(dem::energy(e).total(), energy);  // never gains energy
  }
  EXPECT_LT(velocity(e, 0).norm(), 1e-9);
  EXPECT_LT(spin(e, 0).norm(), 1e-9);
  Frame f;
  dem::fill_frame(e, f);
  ASSERT_EQ(f.contacts->rows(), 2);
  EXPECT_EQ(f.contact_j()[0], partner::wall(Wall::CylinderSide));
  EXPECT_EQ(f.contact_j()[1], partner::wall(Wall::ZLow));
  // At rest each wall pushes by k_n times its overlap, friction is within its cone, the
  // two contacts carry the tilted weight and their torques (lever arm R, Eq. 8) cancel.
  const auto& overlap = f.contacts->get<Eigen::ArrayXd>("overlap");
  Vector3d force = Vector3d::Zero(), torque = Vector3d::Zero();
  for (Eigen::Index k = 0; k < 2; ++k) {
    const Vector3d fn = contact_vector(f, "normal_force", k);
    const Vector3d ft = contact_vector(f, "tangential_force", k);
    EXPECT_NEAR(fn.norm() / (kKn * overlap[k]), 1.0, 1e-6);
    EXPECT_LE(ft.norm(), 0.5 * fn.norm());
    force += fn + ft;
    torque += (-a * fn.normalized()).cross(ft);
  }
  EXPECT_NEAR((force + g).norm(), 0.0, 1e-9);
  EXPECT_NEAR(torque.norm(), 0.0, 1e-9);
}

TEST(DemWalls, SphereOnAVibratedBaseFollowsItWithoutDrift) {
  // Peak acceleration A w^2 = 0.5 g: the sphere never leaves the base, and rides on it at
  // the height of rest (overlap m (g + base acceleration) / k_n) for 10^5 steps.
  dem::ContactMaterial m = material(kKn, 40.0, 0.5);
  dem::Drive drive;
  drive.form = dem::Drive::Form::Sine;
  drive.amplitude = 0.5;
  drive.angular_frequency = 1.0;
  dem::Engine e(one_species(m), dem::WallSet(base_only(), drive), settings(1e-4, -Vector3d::UnitZ()),
                spheres({{0, 0, 0.5 - 1.0 / kKn}}, {{0, 0, 0.5}}));
  double worst = 0.0;
  for (int k = 0; k < 100; ++k) {
    e.run(1000);
    const double base = drive.offset(e.time()).z();
    const double load = 1.0 + 0.5 * -std::sin(e.time());  // g + base acceleration
    worst = std::max(worst, std::abs(0.5 - (position(e, 0).z() - base) - load / kKn) * kKn);
    EXPECT_LT(std::abs(position(e, 0).x()) + std::abs(position(e, 0).y()), 1e-12);
  }
  EXPECT_LT(worst, 0.01);  // of the static overlap
}
