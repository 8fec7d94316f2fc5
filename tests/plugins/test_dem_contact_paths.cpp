// The dem engine's pair and wall paths against the contact evaluator alone
// (dem_two_body.hpp): a head-on collision through the pair lanes and against the base, and a
// sphere rolling to rest, on the base and on a fixed sphere, in the distance the rolling
// model predicts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "dem_two_body.hpp"
#include "engine.hpp"
#include "granpipe/errors.hpp"

namespace dem = granpipe::dem;
using dem_test::Collision;
using dem_test::ContactOf;
using dem_test::evaluator_collision;
using dem_test::kKn;
using dem_test::material;
using Eigen::Vector3d;
using granpipe::Boundary;
using granpipe::Container;

namespace {

constexpr double kUnitMassDensity = 6.0 / std::numbers::pi;  // a sphere of diameter 1 weighs 1

Container open_container() {
  Container c;
  for (auto& axis : c.boundary) axis = {Boundary::Open, Boundary::Open};
  return c;
}

Container base_only() {
  Container c = open_container();
  c.boundary[2][0] = Boundary::Wall;
  return c;
}

dem::InitialState bodies(const std::vector<Vector3d>& x, const std::vector<Vector3d>& v,
                         const std::vector<Vector3d>& w, const std::vector<double>& radius,
                         const std::vector<int>& species) {
  dem::InitialState s;
  const auto n = static_cast<Eigen::Index>(x.size());
  s.position.resize(3, n);
  s.velocity.resize(3, n);
  s.angular_velocity.resize(3, n);
  s.radius.resize(n);
  s.species.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto K = static_cast<std::size_t>(k);
    s.position.col(k) = x[K];
    s.velocity.col(k) = v[K];
    s.angular_velocity.col(k) = w[K];
    s.radius[k] = radius[K];
    s.species[k] = species[K];
  }
  return s;
}

dem::Settings settings(double dt, dem::ContactLaw law, const Vector3d& gravity) {
  dem::Settings s;
  s.dt = dt;
  s.law = law;
  s.gravity = gravity;
  return s;
}

// A collision run by the engine: overlap(e) of its one contact, sampled every step from
// an exact touch at t = 0; the contact time from its zero crossing, the restitution from
// approach_speed(e) after (the approach speed at the start is 1).
Collision engine_collision(dem::Engine& e, const std::function<double(const dem::Engine&)>& overlap,
                           const std::function<double(const dem::Engine&)>& approach_speed) {
  const double dt = e.settings().dt;
  double previous = overlap(e), peak = 0.0;
  while (true) {
    e.run(1);
    const double now = overlap(e);
    peak = std::max(peak, now);
    if (now <= 0.0 && e.step() > 1) {
      return {e.time() - dt + dt * previous / (previous - now), -approach_speed(e), peak};
    }
    previous = now;
  }
}

Vector3d x_of(const dem::Engine& e, int tag) { return e.particles().x.col(e.index_of(tag)); }
Vector3d v_of(const dem::Engine& e, int tag) { return e.particles().v.col(e.index_of(tag)); }

}  // namespace

// Two unit spheres (m_eff = 1/2) meeting head on, and one sphere (m = 1) hitting the base
// (d = 2 R): the engine's pair lanes and wall path step the same scheme as the two-body
// integration above, from the same exact touch, so they must give its contact time,
// restitution and peak overlap to rounding (1e-9 relative: positions are O(1), overlaps
// 1e-3, so the overlap carries 1e-13 of relative rounding per step).
TEST(DemContactEngine, PairLanesAndWallsGiveTheEvaluatorsCollision) {
  for (dem::ContactLaw law : {dem::ContactLaw::Linear, dem::ContactLaw::Hertz}) {
    const dem::ContactMaterial m = material(42.398, 0.5);
    const dem::Model model = dem::Model::uniform(1, kUnitMassDensity, m, m);
    const double dt = 2e-5;
    dem::Engine pair(model, dem::WallSet(open_container(), {}), settings(dt, law, Vector3d::Zero()),
                     bodies({{0, 0, 0}, {1, 0, 0}}, {{0.5, 0, 0}, {-0.5, 0, 0}},
                            {Vector3d::Zero(), Vector3d::Zero()}, {0.5, 0.5}, {0, 0}));
    const Collision by_pair = engine_collision(
        pair, [](const dem::Engine& e) { return 1.0 - (x_of(e, 1) - x_of(e, 0)).norm(); },
        [](const dem::Engine& e) { return (v_of(e, 0) - v_of(e, 1)).x(); });
    dem::Engine wall(model, dem::WallSet(base_only(), {}), settings(dt, law, Vector3d::Zero()),
                     bodies({{0, 0, 0.5}}, {{0, 0, -1}}, {Vector3d::Zero()}, {0.5}, {0}));
    const Collision by_wall = engine_collision(
        wall, [](const dem::Engine& e) { return 0.5 - x_of(e, 0).z(); },
        [](const dem::Engine& e) { return -v_of(e, 0).z(); });
    const auto expected = [&](double m_eff) {
      return law == dem::ContactLaw::Linear
                 ? evaluator_collision<ContactOf<dem::LinearNormal>>(m, m_eff, 1.0, dt)
                 : evaluator_collision<ContactOf<dem::HertzNormal>>(m, m_eff, 1.0, dt);
    };
    for (const auto& [engine, m_eff, path] :
         {std::tuple(by_pair, 0.5, "pair"), std::tuple(by_wall, 1.0, "wall")}) {
      const Collision alone = expected(m_eff);
      EXPECT_NEAR(engine.contact_time / alone.contact_time, 1.0, 1e-9) << path;
      EXPECT_NEAR(engine.restitution / alone.restitution, 1.0, 1e-9) << path;
      EXPECT_NEAR(engine.peak_overlap / alone.peak_overlap, 1.0, 1e-9) << path;
    }
  }
}

namespace {

// How far a sphere of radius 1/2 and mass 1, set rolling without slipping at v0 along x
// on its support (the base, or the top of a fixed sphere of radius `below`), travels
// until it stops (until its speed first drops to 1e-3 v0: the rolling torque's cap then
// holds it).
double rolling_distance(double mu_roll, double v0, double below, dem::ContactLaw law) {
  const double g = 1.0, dt = 1e-4;  // t_c = pi sqrt(m/k_n) = 7e-3 against the base
  const dem::ContactMaterial m = material(42.398, 0.5, mu_roll);
  dem::Model model = dem::Model::uniform(below > 0 ? 2 : 1, kUnitMassDensity, m, m);
  const bool on_base = below == 0.0;
  const double rest = law == dem::ContactLaw::Linear ? g / kKn : std::pow(g / kKn, 2.0 / 3.0);
  std::vector<Vector3d> x{{0, 0, 0.5 - rest}}, v{{v0, 0, 0}}, w{{0, v0 / 0.5, 0}};
  std::vector<double> r{0.5};
  std::vector<int> species{0};
  if (!on_base) {
    model.fixed = {false, true};
    x.push_back({0, 0, -below});
    v.emplace_back(Vector3d::Zero());
    w.emplace_back(Vector3d::Zero());
    r.push_back(below);
    species.push_back(1);
  }
  dem::Engine e(model, dem::WallSet(on_base ? base_only() : open_container(), {}),
                settings(dt, law, {0, 0, -g}), bodies(x, v, w, r, species));
  // Three times the stopping time at mu_r = 0.1.
  const double stop_time = 3.0 * v0 / (5.0 / 7.0 * std::max(mu_roll, 0.1) * g);
  while (v_of(e, 0).norm() > 1e-3 * v0 && e.time() < stop_time) e.run(10);
  return x_of(e, 0).x();
}

}  // namespace

// A sphere rolling on the base against the rolling torque's cap mu_r R |F_n| (R_eff = R
// against a wall) decelerates at (5/7) mu_r g (I = 2/5 m R^2, rolling without slipping:
// the friction it needs, (5/7) mu_r m g, is far inside mu m g) and stops after
// s = 7 v0^2 / (10 mu_r g). Without rolling friction it rolls on at v0. Tolerance 1e-3:
// before the cap the spring winds up by theta_c = mu_r N / (f k_t R): 1e-5 rad for the
// linear law, 6e-4 for Hertz at mu_r = 0.3 (its springs are softer by f = sqrt(delta/d) =
// 0.017 here), which lengthens s by about R theta_c / 2, up to 3e-4 of it; the stop
// criterion (1e-3 v0) adds 1e-6; Verlet is exact for a constant deceleration. Measured:
// 1.4e-5 and 4.4e-5 (linear), 4.1e-5 and 3.8e-4 (Hertz) longer than predicted.
TEST(DemContactEngine, SphereRollingOnTheBaseStopsWhereTheRollingModelPredicts) {
  const double v0 = 0.5, g = 1.0;
  for (dem::ContactLaw law : {dem::ContactLaw::Linear, dem::ContactLaw::Hertz}) {
    for (double mu_roll : {0.1, 0.3}) {
      const double predicted = 7.0 * v0 * v0 / (10.0 * mu_roll * g);
      EXPECT_NEAR(rolling_distance(mu_roll, v0, 0.0, law) / predicted, 1.0, 1e-3)
          << "mu_r " << mu_roll;
    }
    // Without rolling resistance it rolls on: far past where mu_r = 0.1 would stop it.
    EXPECT_GT(rolling_distance(0.0, v0, 0.0, law), 3.0 * 7.0 * v0 * v0 / (10.0 * 0.1 * g));
  }
}

// The same through the pair lanes: rolling on top of a fixed sphere of radius 1000 (R_eff =
// R 1000 / 1000.5). The work of the rolling torque, mu_r R_eff N per radian of relative
// turn (s / R), takes the kinetic energy 7/10 m v0^2 plus the drop s^2 / (2 (1000.5)) of
// rolling down the big sphere's top: a quadratic in s. N departs from m g by the tilt and
// the centripetal term, 3e-4 at most (measured: 1.7e-4 off); tolerance 1e-3 as above.
TEST(DemContactEngine, SphereRollingOnAFixedSphereStopsWhereTheRollingModelPredicts) {
  const double v0 = 0.5, g = 1.0, below = 1000.0, mu_roll = 0.3;
  const double r_eff = 0.5 * below / (0.5 + below);
  const double a = g / (2.0 * (below + 0.5)), b = mu_roll * g * r_eff / 0.5, c = 0.7 * v0 * v0;
  const double predicted = (b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  EXPECT_NEAR(rolling_distance(mu_roll, v0, below, dem::ContactLaw::Linear) / predicted, 1.0, 1e-3);
}

// Twisting through the wall path: a sphere resting on the base and spinning about the
// vertical at w0 feels the capped torque mu_r R m g about its contact normal, so it slows at
// mu_r R m g / (2/5 m R^2) = 2.5 mu_r g / R and stops after t = w0 R / (2.5 mu_r g) (2 here).
// Tolerance 1e-3: the spin is sampled every 10 steps (1e-3, 5e-4 of t) for its first turn
// through zero; the spring's wind-up before the cap, mu_r m g / (k_t R) = 3.5e-6 rad, delays
// the stop by 1e-5.
TEST(DemContactEngine, SphereSpinningOnTheBaseStopsWhenTheTwistingTorquePredicts) {
  const double g = 1.0, w0 = 1.0, mu_roll = 0.1, radius = 0.5;
  const dem::ContactMaterial m = material(42.398, 0.5, mu_roll);
  const dem::Model model = dem::Model::uniform(1, kUnitMassDensity, m, m);
  dem::Engine e(
      model, dem::WallSet(base_only(), {}), settings(1e-4, dem::ContactLaw::Linear, {0, 0, -g}),
      bodies({{0, 0, radius - g / kKn}}, {Vector3d::Zero()}, {{0, 0, w0}}, {radius}, {0}));
  const auto spin = [&] { return e.particles().omega.col(0).z(); };
  while (spin() > 0.0 && e.time() < 10.0) e.run(10);
  EXPECT_NEAR(e.time() / (w0 * radius / (2.5 * mu_roll * g)), 1.0, 1e-3);
}

// A rolling torque acts on rotating spheres through their contacts: rolling friction with
// friction or rotation off is refused, naming the parameter.
TEST(DemContactEngine, RollingFrictionWithoutFrictionOrRotationIsRefused) {
  const dem::ContactMaterial m = material(42.398, 0.5, 0.1);
  const dem::Model model = dem::Model::uniform(1, kUnitMassDensity, m, m);
  for (const auto& [friction, rotation] : {std::pair(false, true), std::pair(true, false)}) {
    dem::Settings s = settings(1e-4, dem::ContactLaw::Linear, Vector3d::Zero());
    s.friction = friction;
    s.rotation = rotation;
    try {
      dem::Engine e(model, dem::WallSet(base_only(), {}), s,
                    bodies({{0, 0, 1}}, {Vector3d::Zero()}, {Vector3d::Zero()}, {0.5}, {0}));
      ADD_FAILURE() << "accepted rolling friction with friction " << friction << ", rotation "
                    << rotation;
    } catch (const granpipe::InputError& error) {
      EXPECT_NE(std::string(error.what()).find("rolling_friction"), std::string::npos);
    }
  }
}
