// Tests of the dem engine against analytic answers: head-on collisions (restitution and
// contact time of Eqs. 9-10, Hertz contact time), energy conservation, friction on an
// incline and the Coulomb cap, rest on the base, walls and their motion, contact history
// across neighbour-list rebuilds, thread-count independence, time-step safety, blow-up
// detection and the emitted frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "diagnostics.hpp"
#include "engine.hpp"
#include "frame_output.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/random.hpp"
#include "loose_lattice.hpp"
#include "plugin_harness.hpp"
#include "time_step.hpp"

namespace dem = granpipe::dem;
using Eigen::Vector3d;
using granpipe::Boundary;
using granpipe::Container;
using granpipe::ContainerShape;
using granpipe::Frame;
using granpipe::InputError;
using granpipe::Wall;
using granpipe::test::input_error_of;
namespace partner = granpipe::partner;

// Every heap allocation of this test program (operator new and Eigen both end in malloc)
// is counted, so that a test can show that time steps allocate nothing. (Arrays of 2 MB and
// more are mapped on huge pages, not malloc'd, and go uncounted: the scenes here stay
// below that.)
namespace {
std::atomic<long> allocations{0};
}  // namespace
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t n) {
  ++allocations;
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) {
  ++allocations;
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) {
  ++allocations;
  return __libc_realloc(p, n);
}
}

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
double crossing(double t0, double f0, double t1, double f1) {
  return t0 + (t1 - t0) * f0 / (f0 - f1);
}

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
  dem::InitialState s = spheres({{0.5, 0.5, 0.5},
                                 {1.5, 0.5, 0.5},
                                 {2.5, 0.5, 0.5},
                                 {0.5, 1.5, 0.5},
                                 {1.5, 1.5, 1.5},
                                 {2.5, 2.5, 0.5},
                                 {0.5, 2.5, 2.5},
                                 {1.5, 2.5, 1.5},
                                 {2.5, 1.5, 2.5},
                                 {0.5, 0.5, 2.5}},
                                {{1, 0.3, -0.2},
                                 {-0.5, 1, 0.1},
                                 {0.2, -0.7, 1},
                                 {-1, -1, 0.4},
                                 {0.6, 0.1, -1},
                                 {0.9, -0.4, 0.3},
                                 {-0.2, 0.8, -0.6},
                                 {0.4, 0.4, 0.9},
                                 {-0.8, 0.2, -0.3},
                                 {0.1, -0.9, 0.7}},
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
  return dem::Engine(one_species(m), dem::WallSet(base_only(), {}), s, spheres({{0, 0, rest}}, {}));
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
  dem::Engine e(one_species(m), dem::WallSet(base_only(), {}), settings(1e-4, -Vector3d::UnitZ()),
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
    const double expected =
        law == dem::ContactLaw::Linear ? 1.0 / kKn : std::pow(1.0 / kKn, 2.0 / 3.0);
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
  // Peak acceleration A w^2 = 0.5 g: the frictional sphere never leaves the base, and
  // rides on it at the height of rest (overlap m (g + base acceleration) / k_n) for 10^6
  // steps, without drifting sideways.
  dem::ContactMaterial m = material(kKn, 40.0, 0.5);
  dem::Drive drive;
  drive.form = dem::Drive::Form::Sine;
  drive.amplitude = 0.5;
  drive.angular_frequency = 1.0;
  dem::Engine e(one_species(m), dem::WallSet(base_only(), drive),
                settings(1e-4, -Vector3d::UnitZ()),
                spheres({{0, 0, 0.5 - 1.0 / kKn}}, {{0, 0, 0.5}}));
  double worst = 0.0;
  for (int k = 0; k < 100; ++k) {
    e.run(10000);
    const double base = drive.offset(e.time()).z();
    const double load = 1.0 + 0.5 * -std::sin(e.time());  // g + base acceleration
    worst = std::max(worst, std::abs(0.5 - (position(e, 0).z() - base) - load / kKn) * kKn);
    EXPECT_LT(std::abs(position(e, 0).x()) + std::abs(position(e, 0).y()), 1e-12);
  }
  EXPECT_LT(worst, 0.01);  // of the static overlap
}

TEST(DemDamping, AirDragBringsAFallingSphereToItsTerminalSlipAgainstTheContainer) {
  // A container rising at the steady V = A w (sine drive, w t << 1 over the run) and a sphere
  // of mass 1 under gravity with b_air = 50: the slip v - V relaxes in m / b_air = 0.02 to
  // -m g / b_air, whatever the container does.
  dem::ContactMaterial m = material(kKn, 40.0, 0.5);
  dem::Drive drive;
  drive.form = dem::Drive::Form::Sine;
  drive.amplitude = 1e3;
  drive.angular_frequency = 1e-3;  // V = 1, accelerating by at most 1e-6 over the run
  dem::Settings s = settings(1e-4, -Vector3d::UnitZ());
  s.air_damping = 50.0;
  dem::Engine e(one_species(m), dem::WallSet(no_walls(), drive), s, spheres({{0, 0, 0}}, {}));
  e.run(10000);  // 50 relaxation times
  EXPECT_NEAR(velocity(e, 0).z() - drive.velocity(e.time()).z(), -1.0 / 50.0, 1e-6);
  EXPECT_NEAR(velocity(e, 0).x(), 0.0, 1e-15);
}

// The lattice scanned each layer's whole square of sites: a cylinder 10^12 diameters wide
// hung even `granpipe validate`. Each row now scans only its chord; the sites and their
// order are a full scan's (here without jitter, an intruder's hole cut out), and a bed of
// a few spheres in a cylinder 10^6 diameters wide is built at once.
TEST(DemLooseLattice, RowsScanOnlyTheirChordAndKeepTheFullScansSites) {
  const double radius = 0.5, spacing = 1.03, cylinder = 6.125, intruder = 1.58;
  const dem::InitialState bed = dem::loose_lattice({.count = 2000,
                                                    .radius = radius,
                                                    .cylinder_radius = cylinder,
                                                    .spacing = spacing,
                                                    .jitter = 0.0,
                                                    .intruder_radius = intruder,
                                                    .seed = 3});
  const double reach = cylinder - radius - 0.01 * radius;
  const Vector3d nut(0.0, 0.0, intruder * 1.01);
  std::vector<Vector3d> full{nut};
  const int half = static_cast<int>(reach / spacing) + 1;
  for (int layer = 0; full.size() < 2001; ++layer) {
    const double z = radius * 1.01 + layer * spacing, shift = layer % 2 ? 0.5 * spacing : 0.0;
    for (int i = -half; i <= half && full.size() < 2001; ++i)
      for (int j = -half; j <= half && full.size() < 2001; ++j) {
        const Vector3d x(i * spacing + shift, j * spacing + shift, z);
        if (std::hypot(x.x(), x.y()) <= reach &&
            (x - nut).norm() >= intruder + radius + 0.01 * radius)
          full.push_back(x);
      }
  }
  ASSERT_EQ(bed.position.cols(), 2001);
  for (Eigen::Index k = 0; k < bed.position.cols(); ++k)
    EXPECT_EQ(Vector3d(bed.position.col(k)), full[static_cast<std::size_t>(k)]) << k;
  const dem::InitialState wide = dem::loose_lattice(
      {.count = 60, .radius = 0.5, .cylinder_radius = 5e5, .spacing = 1.03, .seed = 3});
  ASSERT_EQ(wide.position.cols(), 60);
  for (Eigen::Index k = 0; k < 60; ++k) EXPECT_LE(wide.position.col(k).head<2>().norm(), 5e5);
}

namespace {

// A bed of n unit spheres dropped from a loose lattice into a cylinder of radius R, with
// friction, spin and damping (e = 0.5), each sphere given a random velocity of up to
// `stir` per component, and rolling friction mu_roll.
dem::Engine dropped_bed(int n, double R, dem::Settings s, const dem::Drive& drive = {},
                        double stir = 0.0, double mu_roll = 0.0) {
  dem::InitialState bed = dem::loose_lattice(
      {.count = n, .radius = 0.5, .cylinder_radius = R, .spacing = 1.03, .seed = 7});
  // In random order, so that tags say nothing about where a sphere is.
  granpipe::RandomStream random(11);
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  random.shuffle(order);
  const dem::Vectors lattice = bed.position;
  bed.velocity.resize(3, n);
  for (int i = 0; i < n; ++i) {
    bed.position.col(i) = lattice.col(order[static_cast<std::size_t>(i)]);
    for (int c = 0; c < 3; ++c) bed.velocity(c, i) = random.uniform(-stir, stir);
  }
  dem::ContactMaterial m = material(kKn, dem::damping_for_restitution(0.5, kKn, 0.5), 0.5);
  m.mu_roll = mu_roll;
  return dem::Engine(one_species(m), dem::WallSet(cylinder(R), drive), s, bed);
}

void expect_same_state(const dem::Engine& a, const dem::Engine& b, double tolerance) {
  ASSERT_EQ(a.particles().size(), b.particles().size());
  double worst = 0.0;
  for (int tag = 0; tag < a.particles().size(); ++tag) {
    worst = std::max({worst, (position(a, tag) - position(b, tag)).lpNorm<Eigen::Infinity>(),
                      (velocity(a, tag) - velocity(b, tag)).lpNorm<Eigen::Infinity>(),
                      (spin(a, tag) - spin(b, tag)).lpNorm<Eigen::Infinity>()});
  }
  EXPECT_LE(worst, tolerance);
}

}  // namespace

TEST(DemHistory, ContactThatOpensAndClosesWithinOneListIntervalStartsAfresh) {
  // Two spheres rattling in a small box; the skin is so wide that the list is never
  // rebuilt, so the pair stays listed between its contacts.
  dem::ContactMaterial m = material(kKn, dem::damping_for_restitution(0.9, kKn, 0.5), 0.5);
  dem::Settings s = settings(1e-4);
  s.skin = 5.0;
  dem::Engine e(one_species(m), dem::WallSet(box(0, 2.2), {}), s,
                spheres({{0.6, 0.6, 0.6}, {1.6, 1.5, 1.6}}, {{1.0, 0.8, 0.3}, {-0.7, -1.0, 0.5}}));
  const auto touching = [&] { return (position(e, 0) - position(e, 1)).norm() < 1.0; };
  int contacts = 0;
  double longest = 0.0;  // the largest displacement a contact built up
  bool before = touching();
  for (int k = 0; k < 100000; ++k) {
    e.run(1);
    const bool now = touching();
    const Vector3d u = *e.pair_history(0, 1);
    if (!now) {
      EXPECT_EQ(u, Vector3d::Zero()) << "step " << e.step();
    } else if (!before) {
      // A new contact holds one step of tangential slip, v_t dt, and nothing older.
      ++contacts;
      const double slip =
          (velocity(e, 0) - velocity(e, 1)).norm() + 0.5 * (spin(e, 0).norm() + spin(e, 1).norm());
      EXPECT_LE(u.norm(), 1.5 * slip * s.dt) << "contact " << contacts;
    }
    longest = std::max(longest, u.norm());
    before = now;
  }
  EXPECT_EQ(e.neighbors().builds(), 1);
  EXPECT_GE(contacts, 3);
  EXPECT_GT(longest, 10 * 2.0 * s.dt);  // contacts did build up history worth leaking
}

TEST(DemHistory, SurvivesNeighbourListRebuildsAndReordering) {
  // The same settling bed with a skin so thin that the list is rebuilt (and the particles
  // re-sorted) every few steps, and one so wide that it never is: the same trajectories.
  dem::Settings thin = settings(1e-4, -Vector3d::UnitZ()), wide = thin;
  thin.skin = 0.002;
  wide.skin = 2.0;
  dem::Engine a = dropped_bed(60, 2.5, thin), b = dropped_bed(60, 2.5, wide);
  a.run(10000);
  b.run(10000);
  EXPECT_GT(a.neighbors().builds(), 100);
  EXPECT_EQ(b.neighbors().builds(), 1);
  EXPECT_GT(dem::energy(a).tangential_elastic, 0.0);
  expect_same_state(a, b, 1e-12);
}

TEST(DemThreads, OneAndTwoThreadsGiveBitIdenticalRuns) {
  // A stirred bed on a base that moves up at once (a sine drive), listed with a thin skin
  // so that the list is rebuilt and the particles re-sorted several times. (Few steps: on
  // a loaded machine every step's barriers can wait for a descheduled thread.)
  dem::Drive drive;
  drive.form = dem::Drive::Form::Sine;
  drive.amplitude = 0.5;
  drive.angular_frequency = 2.0;
  dem::Settings one = settings(1e-4, -Vector3d::UnitZ()), two = one;
  one.skin = two.skin = 0.002;
  two.threads = 2;
  dem::Engine a = dropped_bed(400, 4.0, one, drive, 1.0),
              b = dropped_bed(400, 4.0, two, drive, 1.0);
  a.run(600);
  b.run(600);
  EXPECT_GT(a.neighbors().builds(), 5);
  EXPECT_GT(dem::energy(a).tangential_elastic, 0.0);
  expect_same_state(a, b, 0.0);
}

TEST(DemThreads, ThreeThreadsSharingTheForceLoopByWorkGiveTheOneThreadRun) {
  // The force loop gives each thread a share of the estimated work (particles, listed pairs,
  // pairs in contact at the last build), not of the particles: three shares of a falling
  // bed, its list rebuilt several times, must still cover every particle exactly once.
  dem::Settings one = settings(1e-4, -Vector3d::UnitZ()), three = one;
  one.skin = three.skin = 0.002;
  three.threads = 3;
  dem::Engine a = dropped_bed(300, 3.0, one, {}, 1.0), b = dropped_bed(300, 3.0, three, {}, 1.0);
  a.run(400);
  b.run(400);
  const auto& work = b.neighbors().work_before;
  ASSERT_EQ(work.size(), static_cast<std::size_t>(b.particles().size()) + 1);
  EXPECT_EQ(work.front(), 0.0);
  EXPECT_TRUE(std::is_sorted(work.begin(), work.end()));
  EXPECT_GT(work.back(), static_cast<double>(b.neighbors().pairs()));
  EXPECT_GT(a.neighbors().builds(), 2);
  expect_same_state(a, b, 0.0);
}

TEST(DemThreads, RunsCutIntoPiecesGiveTheSameRun) {
  // A source emits frames between calls to run(): where it cuts must change nothing.
  dem::Settings s = settings(1e-4, -Vector3d::UnitZ());
  s.skin = 0.002;
  dem::Engine a = dropped_bed(100, 2.5, s, {}, 1.0), b = dropped_bed(100, 2.5, s, {}, 1.0);
  a.run(600);
  for (int k = 0; b.step() < 600; ++k) b.run(std::min<std::int64_t>(k % 3 + 1, 600 - b.step()));
  ASSERT_EQ(b.step(), 600);
  EXPECT_GT(a.neighbors().builds(), 5);
  expect_same_state(a, b, 0.0);
}

TEST(DemThreads, StepsThatRecordAFrameChangeNoStep) {
  // A frame's step keeps its reactions in their slots for the frame (they are cleared before
  // the next force pass): recording contacts now and then must leave the run as it was.
  dem::Settings s = settings(1e-4, -Vector3d::UnitZ());
  s.skin = 0.002;
  dem::Engine a = dropped_bed(100, 2.5, s, {}, 1.0), b = dropped_bed(100, 2.5, s, {}, 1.0);
  a.run(600);
  while (b.step() < 600) {
    b.record_contacts(false);
    b.run(49);
    b.record_contacts(true);
    b.run(1);
    ASSERT_TRUE(b.contacts_recorded());
  }
  EXPECT_GT(a.neighbors().builds(), 5);
  expect_same_state(a, b, 0.0);
}

TEST(DemPaths, EveryInstructionSetGivesTheBaselinesRunWithinRounding) {
  // The loops compiled for each instruction set this processor runs against the baseline
  // (2 lanes, no FMA), every combination of the contact's parts, on the stirred bed of the
  // thread tests: the same run up to rounding. (Few steps: a bed's contacts amplify a
  // difference in the last bit by about tenfold per hundred steps here.)
  dem::Drive drive;
  drive.form = dem::Drive::Form::Sine;
  drive.amplitude = 0.5;
  drive.angular_frequency = 2.0;
  int compared = 0;
  for (const auto law : {dem::ContactLaw::Linear, dem::ContactLaw::Hertz}) {
    for (const auto& [friction, rotation, mu_roll] : {std::tuple{false, false, 0.0},
                                                      {true, false, 0.0},
                                                      {true, true, 0.0},
                                                      {true, true, 0.1}}) {
      dem::Settings s = settings(1e-4, -Vector3d::UnitZ());
      s.skin = 0.002;
      s.law = law;
      s.friction = friction;
      s.rotation = rotation;
      s.instruction_set = dem::InstructionSet::Baseline;
      dem::Engine baseline = dropped_bed(200, 3.0, s, drive, 1.0, mu_roll);
      baseline.run(300);
      for (const auto path : {dem::InstructionSet::Avx2, dem::InstructionSet::Avx512}) {
        if (!dem::runs_here(path)) continue;
        s.instruction_set = path;
        dem::Engine e = dropped_bed(200, 3.0, s, drive, 1.0, mu_roll);
        e.run(300);
        SCOPED_TRACE(std::string(dem::name_of(path)) +
                     (law == dem::ContactLaw::Hertz ? " hertz" : " linear") + " friction " +
                     std::to_string(friction) + " rotation " + std::to_string(rotation) +
                     " mu_roll " + std::to_string(mu_roll));
        EXPECT_EQ(e.instruction_set(), path);
        expect_same_state(baseline, e, 1e-10);
        ++compared;
      }
    }
  }
  if (compared == 0) GTEST_SKIP() << "this processor runs the baseline path only";
}

TEST(DemLanes, AContactsForceDoesNotDependOnTheContactsComputedWithIt) {
  // The force loop computes touching pairs a batch of lanes at a time (blocks of 128 listed
  // pairs, padded batches, materials by lane): 150 far-apart dimers of five kinds (one
  // sliding) feel, bit for bit, what each dimer feels alone. With 1, 2 and 3 species (one
  // material, a table in registers, a gathered table).
  for (int species = 1; species <= 3; ++species) {
    dem::Model model = dem::Model::uniform(species, kUnitMassDensity, material(kKn, 40.0, 0.5),
                                           material(kKn, 40.0, 0.5));
    for (int a = 0; a < species; ++a) {
      for (int b = a; b < species; ++b) {
        model.set_pair(a, b, material(kKn * (1 + a + b), 30.0 + a, 0.4));
      }
    }
    const auto dimer = [&](int d, dem::InitialState& s, Eigen::Index at) {
      const int kind = d % 5;
      const Vector3d x(8.0 * d, 0, 0);
      const Vector3d v = kind == 4 ? Vector3d(0, 5, 0)  // slides
                                   : Vector3d(0.1 * kind, 0.3 - 0.1 * kind, 0.05 * kind);
      s.position.col(at) = x;
      s.position.col(at + 1) = x + Vector3d(0.9375, 0.125, 0.0625);
      s.velocity.col(at) = v;
      s.velocity.col(at + 1) = -v;
      s.angular_velocity.col(at) = Vector3d(0, 0, 2.0 * kind);
      s.angular_velocity.col(at + 1) = Vector3d(1.0 * kind, 0, 0);
      s.species[at] = d % species;
      s.species[at + 1] = d / species % species;
    };
    const auto state = [](Eigen::Index n) {
      dem::InitialState s =
          spheres(std::vector<Vector3d>(static_cast<std::size_t>(n), Vector3d::Zero()), {});
      s.angular_velocity.resize(3, n);
      return s;
    };
    const int dimers = 150;
    dem::InitialState all = state(2 * dimers);
    for (int d = 0; d < dimers; ++d) dimer(d, all, 2 * d);
    const dem::Engine e(model, dem::WallSet(no_walls(), {}), settings(1e-4), all);
    ASSERT_GT(e.neighbors().pairs(), 128);
    for (int d = 0; d < dimers; ++d) {
      dem::InitialState one = state(2);
      dimer(d, one, 0);
      const dem::Engine alone(model, dem::WallSet(no_walls(), {}), settings(1e-4), one);
      for (int k = 0; k < 2; ++k) {
        const int i = e.index_of(2 * d + k), j = alone.index_of(k);
        ASSERT_EQ(e.particles().force.col(i), alone.particles().force.col(j)) << "dimer " << d;
        ASSERT_EQ(e.particles().torque.col(i), alone.particles().torque.col(j)) << "dimer " << d;
      }
    }
  }
}

TEST(DemNeighbours, HalfListHoldsEveryNearPairOnceWithBigParticlesAmongSmallOnes) {
  // Small spheres of two sizes and four intruders 3.16 times larger, scattered at random.
  granpipe::RandomStream random(3);
  dem::InitialState s;
  const int n = 400;
  s.position.resize(3, n);
  s.radius.resize(n);
  for (int i = 0; i < n; ++i) {
    s.position.col(i) =
        Vector3d(random.uniform(0, 12), random.uniform(0, 12), random.uniform(0, 12));
    s.radius[i] = i % 100 == 0 ? 1.58 : i % 2 ? 0.5 : 0.6;
  }
  s.species = Eigen::ArrayXi::Zero(n);
  dem::Settings st = settings(1e-4);
  dem::Engine e(one_species(material(kKn, 0.0, 0.5)), dem::WallSet(no_walls(), {}), st, s);
  const dem::Particles& p = e.particles();
  const double skin = e.skin();
  EXPECT_DOUBLE_EQ(skin, 0.2 * 1.0);
  std::set<std::pair<int, int>> listed;
  for (int i = 0; i < p.size(); ++i) {
    for (std::int32_t k = e.neighbors().first[i]; k < e.neighbors().first[i + 1]; ++k) {
      const int j = e.neighbors().partner[k];
      EXPECT_TRUE(listed.insert(std::minmax(p.tag[i], p.tag[j])).second) << "listed twice";
    }
  }
  std::set<std::pair<int, int>> near;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double reach = s.radius[i] + s.radius[j] + skin;
      if ((s.position.col(i) - s.position.col(j)).squaredNorm() < reach * reach)
        near.insert({i, j});
    }
  }
  EXPECT_EQ(listed, near);
  EXPECT_GT(near.size(), 100u);
}

TEST(DemNeighbours, IntruderOnABedFeelsTheSumOfItsManyContacts) {
  // One sphere of diameter 3.16 (221 times heavier) dropped on a bed of small ones: its
  // force is the sum of its contacts in the emitted table, and the forces on all
  // particles add up to the wall forces alone (each pair's reaction reached its partner).
  // The intruder sits on the base at the axis, in a loose bed that settles around it.
  const double big = 1.58;
  const dem::InitialState lattice = dem::loose_lattice(
      {.count = 300, .radius = 0.5, .cylinder_radius = 3.0, .spacing = 1.03, .seed = 2});
  const Vector3d centre(0, 0, big);
  std::vector<Vector3d> x{centre};
  for (Eigen::Index k = 0; k < lattice.radius.size(); ++k) {
    if ((lattice.position.col(k) - centre).norm() > big + 0.55)
      x.push_back(lattice.position.col(k));
  }
  dem::InitialState bed = spheres(x, {});
  bed.radius[0] = big;
  bed.species[0] = 1;
  const int n = 0;  // the intruder's tag
  dem::ContactMaterial m = material(kKn, 40.0, 0.5);
  dem::Model model = dem::Model::uniform(2, 1.91, m, m);
  model.density[1] = 13.54;
  dem::Engine e(model, dem::WallSet(cylinder(3.0), {}), settings(2e-4, -Vector3d::UnitZ()), bed);
  e.record_contacts(true);
  e.run(20000);
  Frame f;
  dem::fill_frame(e, f);
  Vector3d on_intruder = Vector3d::Zero(), on_walls = Vector3d::Zero();
  int intruder_contacts = 0;
  for (Eigen::Index k = 0; k < f.contacts->rows(); ++k) {
    const Vector3d force =
        contact_vector(f, "normal_force", k) + contact_vector(f, "tangential_force", k);
    if (f.contact_i()[k] == n || f.contact_j()[k] == n) {
      ++intruder_contacts;
      on_intruder += f.contact_i()[k] == n ? force : Vector3d(-force);
    }
    if (partner::is_wall(f.contact_j()[k])) on_walls += force;
  }
  const double weight = 221.0;
  EXPECT_GE(intruder_contacts, 10);
  EXPECT_LT((e.particles().force.col(e.index_of(n)) - on_intruder).norm(), 1e-12 * weight);
  EXPECT_LT((e.particles().force.rowwise().sum() - on_walls).norm(), 1e-12 * weight);
}

namespace {

// The Brazil-nut materials of the paper's Table I: small spheres (d = 1, density 1.91,
// mass 1.0) and the intruder (d = 3.16, density 13.54, mass 221), gamma_t = gamma_n / 2 (the
// dem source's default).
dem::Model bnp_model() {
  const dem::ContactMaterial m{2e5, 2.0 / 7.0 * 2e5, 40.0, 20.0, 0.5};
  dem::Model model = dem::Model::uniform(2, 1.91, m, {2e5, 2.0 / 7.0 * 2e5, 40.0, 20.0, 0.5});
  model.density[1] = 13.54;
  return model;
}

}  // namespace

TEST(DemTimeStep, ShortestContactIsBetweenTheLightestSpheres) {
  Eigen::ArrayXd radius(3);
  radius << 0.5, 1.58, 0.5;
  Eigen::ArrayXi species(3);
  species << 0, 1, 0;
  const dem::ContactTime t =
      dem::smallest_contact_time(bnp_model(), dem::WallSet(cylinder(6.125), {}), radius, species,
                                 dem::ContactLaw::Linear, 0.0);
  const double small = 1.91 * std::numbers::pi / 6.0;
  EXPECT_DOUBLE_EQ(t.t_c, dem::linear_contact_time(2e5, 40.0, small / 2));
  EXPECT_NEAR(t.t_c, 4.97e-3, 1e-5);
  EXPECT_EQ(t.between, "species 0 and species 0");
  // The paper's dt = 2e-4 is t_c/24.8: fine. Larger steps are warned about, then refused.
  EXPECT_EQ(dem::check_time_step(2e-4, t).verdict, dem::StepVerdict::Fine);
  EXPECT_EQ(dem::check_time_step(2e-4, t).message, "");
  const dem::StepCheck warn = dem::check_time_step(3e-4, t);
  EXPECT_EQ(warn.verdict, dem::StepVerdict::Warn);
  EXPECT_EQ(warn.message,
            "dem: dt = 0.0003 is t_c/16.5665 for the shortest contact (species 0 and species 0, "
            "t_c = 0.00496996): above t_c/20, the contact time and restitution lose accuracy");
  const dem::StepCheck refuse = dem::check_time_step(6e-4, t);
  EXPECT_EQ(refuse.verdict, dem::StepVerdict::Refuse);
  EXPECT_EQ(refuse.message,
            "dem: dt = 0.0006 is t_c/8.28327 for the shortest contact (species 0 and species 0, "
            "t_c = 0.00496996): expected dt <= t_c/10 = 0.000496996 (or that pair's contact "
            "longer: t_c is the shortest its normal law, tangential spring and dashpot and "
            "rolling spring give; stiffer k_n, k_t, k_roll and larger gamma_n, gamma_t shorten "
            "it)");
  // Without a tangential dashpot the tangential spring (k_t = 2/7 k_n on 2/7 m_eff, so the
  // normal spring's undamped period) is the shorter.
  dem::Model undamped = bnp_model();
  for (dem::ContactMaterial& m : undamped.pair) m.gamma_t = 0.0;
  const dem::ContactTime u = dem::smallest_contact_time(
      undamped, dem::WallSet(cylinder(6.125), {}), radius, species, dem::ContactLaw::Linear, 0.0);
  EXPECT_DOUBLE_EQ(u.t_c, dem::linear_contact_time(2.0 / 7.0 * 2e5, 0.0, 2.0 / 7.0 * small / 2));
}

// A contact damped ten times past critical (2 sqrt(k_n / m_eff) = 1265): Eq. (10) has no
// period, the undamped one let dt = 2.485e-4 pass, and that step (gamma_n dt = 3) threw the
// spheres apart at about twice their approach speed. The dashpot's 2 pi / gamma_n decides
// the step; within it they part no faster than they met.
TEST(DemTimeStep, ADashpotPastCriticalDampingDecides) {
  const double gamma = 1.2e4;
  const dem::Model model = one_species(material(kKn, gamma, 0.0));
  const dem::ContactTime t = dem::smallest_contact_time(
      model, dem::WallSet(no_walls(), {}), Eigen::ArrayXd::Constant(2, 0.5),
      Eigen::ArrayXi::Zero(2), dem::ContactLaw::Linear, 0.0);
  EXPECT_DOUBLE_EQ(t.t_c, 2.0 * std::numbers::pi / gamma);
  EXPECT_EQ(dem::check_time_step(2.485e-4, t).verdict, dem::StepVerdict::Refuse);
  // The fastest relative speed after the spheres meet, at each step.
  auto fastest_after_contact = [&](double dt) {
    dem::Engine e(model, dem::WallSet(no_walls(), {}), settings(dt),
                  spheres({{0, 0, 0}, {1.001, 0, 0}}, {{0.5, 0, 0}, {-0.5, 0, 0}}));
    double fastest = 0.0;
    for (int k = 0; k < 4000 && e.time() < 0.05; ++k) {
      e.run(1);
      fastest = std::max(fastest, (velocity(e, 1) - velocity(e, 0)).norm());
    }
    return fastest;
  };
  EXPECT_GT(fastest_after_contact(2.485e-4), 1.5);  // the step refused: unstable
  EXPECT_LE(fastest_after_contact(t.t_c / 20), 1.0 + 1e-12);
}

TEST(DemTimeStep, WallsAndStiffSpeciesCountToo) {
  // Only intruders, and a base stiffer than the spheres: the wall decides.
  dem::Model model = bnp_model();
  model.wall[static_cast<int>(Wall::ZLow) * 2 + 1].kn = 1e8;
  Eigen::ArrayXd radius = Eigen::ArrayXd::Constant(2, 1.58);
  Eigen::ArrayXi species = Eigen::ArrayXi::Constant(2, 1);
  const dem::ContactTime t = dem::smallest_contact_time(
      model, dem::WallSet(cylinder(6.125), {}), radius, species, dem::ContactLaw::Linear, 0.0);
  EXPECT_EQ(t.between, "species 1 and wall z_low");
  // Hertz contacts need the impact speed.
  EXPECT_THROW(
      {
        try {
          dem::smallest_contact_time(model, dem::WallSet(cylinder(6.125), {}), radius, species,
                                     dem::ContactLaw::Hertz, 0.0);
        } catch (const InputError& e) {
          EXPECT_STREQ(e.what(),
                       "dem: impact speed for the Hertz contact time: expected a finite "
                       "value > 0, got 0");
          throw;
        }
      },
      InputError);
  const dem::ContactTime hertz = dem::smallest_contact_time(
      model, dem::WallSet(cylinder(6.125), {}), radius, species, dem::ContactLaw::Hertz, 5.0);
  EXPECT_LT(hertz.t_c, dem::hertz_contact_time(2e5, 3.16, 0.5 * 221, 5.0));
}

TEST(DemPaths, AnInstructionSetThisProcessorLacksIsRefusedByName) {
  for (const auto path : {dem::InstructionSet::Avx2, dem::InstructionSet::Avx512}) {
    if (dem::runs_here(path)) continue;
    dem::Settings s = settings(1e-4);
    s.instruction_set = path;
    EXPECT_EQ(input_error_of([&] { dropped_bed(10, 2.0, s); }),
              std::string("dem: instruction_set: expected an instruction set this processor runs, "
                          "found \"") +
                  dem::name_of(path) + "\" (" + dem::label_of(path) +
                  " is missing here; \"auto\" takes the widest it has)");
  }
}

TEST(DemInput, BadParticlesSettingsAndWallsAreRefusedByName) {
  const dem::Model model = one_species(material(kKn, 10.0, 0.5));
  const dem::WallSet walls(base_only(), {});
  const auto make = [&](const dem::InitialState& s, const dem::Settings& st = settings(1e-4)) {
    return input_error_of([&] { dem::Engine(model, walls, st, s); });
  };
  dem::InitialState s = spheres({{0, 0, 1}, {2, 0, 1}}, {});
  s.radius[1] = -1;
  EXPECT_EQ(make(s), "dem: particle 1: radius: expected a finite value > 0, got -1");
  s = spheres({{0, 0, 1}, {2, 0, 1}}, {});
  s.species[0] = 3;
  EXPECT_EQ(make(s), "dem: particle 0: species: expected a species in 0..0, got 3");
  s = spheres({{0, 0, 1}, {2, 0, std::nan("")}}, {});
  EXPECT_EQ(make(s), "dem: particle 1: position z: expected a finite value, got nan");
  s = spheres({{0, 0, 1}, {2, 0, 1}}, {});
  s.velocity.resize(3, 1);
  EXPECT_EQ(make(s), "dem: initial velocity: expected 2 vectors (one per particle), got 1");
  EXPECT_EQ(make(spheres({{0, 0, 1}, {0, 0, 1}}, {})),
            "dem: particles 0 and 1: expected distinct centres, got the same position (no "
            "contact normal exists)");
  EXPECT_EQ(make(spheres({{0, 0, 1}}, {}), settings(0.0)),
            "dem: dt: expected a finite time step > 0, got 0");
  dem::Settings threads = settings(1e-4);
  threads.threads = 0;
  EXPECT_EQ(make(spheres({{0, 0, 1}}, {}), threads), "dem: threads: expected at least 1, got 0");

  dem::Model bad = model;
  bad.pair[0].mu = -0.5;
  EXPECT_EQ(input_error_of([&] { bad.check(); }),
            "dem: species 0 with 0: mu: expected a finite value >= 0, got -0.5");
  bad = model;
  bad.density[0] = 0;
  EXPECT_EQ(input_error_of([&] { bad.check(); }),
            "dem: species 0: density: expected a finite value > 0, got 0");

  Container periodic = base_only();
  periodic.boundary[0] = {Boundary::Periodic, Boundary::Periodic};
  EXPECT_EQ(input_error_of([&] { dem::WallSet(periodic, {}); }),
            "dem: container: x_low: expected a wall or an open side, got a periodic side (the "
            "DEM engine has no periodic boundaries)");
  dem::Drive tilted;
  tilted.direction = Vector3d(1, 1, 0);
  EXPECT_EQ(input_error_of([&] { dem::WallSet(base_only(), tilted); }),
            "dem: drive direction: expected a unit vector, got (1 1 0)");
}

TEST(DemHealth, ParticleThroughTheBaseOrNotFiniteStopsTheRun) {
  const dem::Model model = one_species(material(10.0, 0.0, 0.5));
  // So fast that one step takes it through the base: the engine stops it in that step.
  dem::Engine through(model, dem::WallSet(base_only(), {}), settings(1e-3),
                      spheres({{0, 0, 0.6}, {5, 0, 3}}, {{0, 0, -2000}, {0, 0, 0}}));
  EXPECT_NO_THROW(dem::check_health(through, 1e9));
  EXPECT_EQ(input_error_of([&] { through.run(1); }),
            "dem: step 1 (t = 0.001): particle 0 overlaps wall z_low by 380 % of its radius (a "
            "sound run stays within 30 %): the contacts are too soft for the speed of impact, or "
            "dt too long; raise k_n, lower the speeds or reduce dt (now 0.001)");
  // A velocity that overflows the position.
  dem::Engine overflow(model, dem::WallSet(no_walls(), {}), settings(10.0),
                       spheres({{0, 0, 0}, {5, 0, 0}}, {{0, 0, 0}, {1e308, 0, 0}}));
  overflow.run(1);
  EXPECT_EQ(dem::first_non_finite(overflow), 1);
  EXPECT_THROW(dem::check_health(overflow, 1e9), dem::BlowUp);
  // An energy above the bound.
  dem::Engine fast(model, dem::WallSet(no_walls(), {}), settings(1e-3),
                   spheres({{0, 0, 0}}, {{3, 0, 0}}));
  EXPECT_NO_THROW(dem::check_health(fast, 4.5));
  EXPECT_EQ(input_error_of([&] { dem::check_health(fast, 4.0); }),
            "dem: step 0 (t = 0): kinetic energy 4.5 exceeds 4: the run blew up; reduce dt (now "
            "0.001) against the shortest contact time, or the initial overlaps");
}

namespace {

// Two spheres meeting head on at relative speed 1e3 (far faster than k_n = 2e5 can stop)
// under each kernel; the message of the stop.
std::string pass_through(dem::ContactLaw law, bool friction, bool rotation, int threads) {
  dem::Settings s = settings(2e-4);
  s.law = law;
  s.friction = friction;
  s.rotation = rotation;
  s.threads = threads;
  dem::Engine e(one_species(material(kKn, 40.0, 0.5)), dem::WallSet(no_walls(), {}), s,
                spheres({{-2, 0, 0}, {2, 0, 0}}, {{500, 0, 0}, {-500, 0, 0}}));
  const std::string m = input_error_of([&] { e.run(100); });
  // The spheres are stopped before they pass through each other.
  EXPECT_LT(position(e, 0).x(), position(e, 1).x());
  return m;
}

}  // namespace

TEST(DemHealth, EveryKernelStopsAContactPastTheOverlapLimitInTheStepItHappens) {
  // 3 of gap closed at 0.2 per step: the contact starts in step 15 and its overlap passes
  // 0.3 of the radius (0.15) in step 16.
  const std::string expected = "dem: step 16 (t = 0.0032): particles 0 and 1 overlap by ";
  for (const dem::ContactLaw law : {dem::ContactLaw::Linear, dem::ContactLaw::Hertz}) {
    for (const auto& [friction, rotation] :
         {std::pair{false, false}, std::pair{true, false}, std::pair{true, true}}) {
      const std::string one = pass_through(law, friction, rotation, 1);
      EXPECT_EQ(one.rfind(expected, 0), 0u) << one;
      EXPECT_NE(one.find(" % of the smaller radius (a sound run stays within 30 %): the contacts "
                         "are too soft for the speed of impact, or dt too long; raise k_n, lower "
                         "the speeds or reduce dt (now 0.0002)"),
                std::string::npos)
          << one;
      EXPECT_EQ(pass_through(law, friction, rotation, 2), one);  // the same step and overlap
    }
  }
}

TEST(DemHealth, AContactWithinTheOverlapLimitRunsOn) {
  // Relative speed 30: the linear law's undamped overlap v sqrt(m_eff / k_n) is 0.047, 9.5 %
  // of the radius.
  dem::Engine e(one_species(material(kKn, 40.0, 0.5)), dem::WallSet(no_walls(), {}), settings(2e-4),
                spheres({{-1, 0, 0}, {1, 0, 0}}, {{15, 0, 0}, {-15, 0, 0}}));
  EXPECT_NO_THROW(e.run(200));
  EXPECT_GT(velocity(e, 1).x(), 0.0);  // bounced
}

TEST(DemFrame, RowsFollowTheCallersOrderWithContactsOfPairsAndWalls) {
  // Three spheres in a column on the base, given top first so that the engine re-sorts
  // them, with a fourth one far away.
  dem::ContactMaterial m = material(kKn, 40.0, 0.5);
  const double d = 1.0 - 1e-4;
  dem::Engine e(one_species(m), dem::WallSet(base_only(), {}), settings(1e-4, -Vector3d::UnitZ()),
                spheres({{0, 0, 0.5 + 2 * d}, {0, 0, 0.5 + d}, {0, 0, 0.5}, {5, 0, 3}},
                        {{0.1, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}}));
  Frame f;
  EXPECT_THROW(dem::fill_frame(e, f), granpipe::InternalError);  // walls not recorded
  e.record_contacts(true);
  e.run(10);
  dem::fill_frame(e, f);
  EXPECT_NO_THROW(f.check("dem frame"));
  EXPECT_EQ(f.step, 10);
  EXPECT_DOUBLE_EQ(f.time, 10 * 1e-4);
  EXPECT_EQ(f.container.shape, ContainerShape::Box);
  ASSERT_EQ(f.size(), 4);
  for (int tag = 0; tag < 4; ++tag) {
    EXPECT_EQ(f.id()[tag], tag);
    EXPECT_EQ(f.position().row(tag).matrix().transpose(), position(e, tag));
    EXPECT_EQ(f.table<double>("velocity").row(tag).matrix().transpose(), velocity(e, tag));
    EXPECT_EQ(f.table<double>("angular_velocity").row(tag).matrix().transpose(), spin(e, tag));
  }
  // Sphere 2 on the base, 1 on 2, 0 on 1: sorted by (i, j), the wall as j < 0 first.
  ASSERT_EQ(f.contacts->rows(), 3);
  EXPECT_EQ(f.contact_i()[0], 0);
  EXPECT_EQ(f.contact_j()[0], 1);
  EXPECT_EQ(f.contact_i()[1], 1);
  EXPECT_EQ(f.contact_j()[1], 2);
  EXPECT_EQ(f.contact_i()[2], 2);
  EXPECT_EQ(f.contact_j()[2], partner::wall(Wall::ZLow));
  // Forces on i, which is the upper partner in every contact here: pushed up.
  for (Eigen::Index k = 0; k < 3; ++k) EXPECT_GT(contact_vector(f, "normal_force", k).z(), 0.0);
  // Sphere 0 slides on sphere 1: its friction points back.
  EXPECT_LT(contact_vector(f, "tangential_force", 0).x(), 0.0);
  const auto& overlap = f.contacts->get<Eigen::ArrayXd>("overlap");
  // Contact points in the middle of the overlaps.
  EXPECT_NEAR(contact_vector(f, "point", 2).z(), -0.5 * overlap[2], 1e-15);
  EXPECT_NEAR(contact_vector(f, "point", 1).z(), position(e, 2).z() + 0.5 - 0.5 * overlap[1],
              1e-12);
}

TEST(DemFrame, TheWallRecordsAreReadOnceAndFreed) {
  // The records hold two vectors per particle and wall: a frame reads them and lets them go,
  // and the next recorded step records again.
  dem::Engine e(one_species(material(kKn, 40.0, 0.5)), dem::WallSet(base_only(), {}),
                settings(1e-4, -Vector3d::UnitZ()), spheres({{0, 0, 0.5 - 1e-4}}, {{0, 0, 0}}));
  e.record_contacts(true);
  e.run(3);
  Frame f;
  dem::fill_frame(e, f);
  ASSERT_EQ(f.contacts->rows(), 1);
  const Vector3d first = contact_vector(f, "normal_force", 0);
  EXPECT_GT(first.z(), 0.0);
  EXPECT_EQ(e.recorded_wall_normal()[0].cols(), 0);
  EXPECT_EQ(e.recorded_wall_tangential()[0].cols(), 0);
  EXPECT_FALSE(e.contacts_recorded());
  EXPECT_THROW(dem::fill_frame(e, f), granpipe::InternalError);
  e.run(1);
  dem::fill_frame(e, f);
  ASSERT_EQ(f.contacts->rows(), 1);
  EXPECT_EQ(f.contact_j()[0], partner::wall(Wall::ZLow));
  EXPECT_GT(contact_vector(f, "normal_force", 0).z(), 0.0);
}

TEST(DemMemory, TimeStepsWithoutARebuildAllocateNothing) {
  dem::Drive drive;
  drive.amplitude = 1.0;
  drive.angular_frequency = 2.0 * std::numbers::pi * 0.5;  // 4 g: the bed flies and lands
  const long at_start = allocations.load();
  dem::Engine e = dropped_bed(300, 3.0, settings(1e-4, -Vector3d::UnitZ()), drive);
  ASSERT_GT(allocations.load(), at_start) << "the counter sees the engine's arrays";
  e.run(2000);
  long steps_without_rebuild = 0;
  for (int k = 0; k < 5000; ++k) {
    const std::int64_t builds = e.neighbors().builds();
    const long before = allocations.load();
    e.run(1);
    if (e.neighbors().builds() != builds) continue;  // a rebuild may need more room
    ++steps_without_rebuild;
    ASSERT_EQ(allocations.load(), before) << "step " << e.step();
  }
  EXPECT_GT(steps_without_rebuild, 1000);
}
