// Tests of the dem contact evaluator (plugins/dem/contact_evaluator.hpp) alone, each part
// and each combination, against analytic two-body answers: the linear law's restitution
// and contact time (the damped oscillator), the Hertz contact's duration and peak overlap
// (and, damped, a fine Runge-Kutta integration of its equation), the tangential
// stick-slip at mu |F_n|, the rolling spring and its cap; the lanes of the pair loop
// against the
// scalar wall arithmetic. (The engine's paths against the evaluator:
// test_dem_contact_paths.cpp.)
//
// This file is compiled for the force loops' instruction set (tests/CMakeLists.txt), so
// LaneMath here has the pair loop's width; it therefore uses nothing of the engine, whose
// Eigen objects the plugin allocates with the baseline's alignment.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "contact_evaluator.hpp"
#include "dem_two_body.hpp"

namespace dem = granpipe::dem;
using dem::LaneMath;
using dem::ScalarMath;
using dem::Vec4;
using dem_test::Collision;
using dem_test::ContactOf;
using dem_test::evaluator_collision;
using dem_test::kKn;
using dem_test::material;
using Eigen::Vector3d;

namespace {

// The same collision integrated by classical Runge-Kutta from the equation of motion
// m_eff delta'' = -f (k_n delta + gamma_n m_eff delta') alone (no evaluator), f = sqrt(delta/d).
Collision hertz_by_runge_kutta(const dem::ContactMaterial& m, double m_eff, double d, double dt) {
  const auto rhs = [&](double delta, double rate) {
    const double f = std::sqrt(std::max(delta, 0.0) / d);
    return -f * (m.kn * delta + m.gamma_n * m_eff * rate) / m_eff;
  };
  double delta = 0.0, rate = 1.0, t = 0.0, peak = 0.0;
  while (true) {
    const double k1x = rate, k1v = rhs(delta, rate);
    const double k2x = rate + 0.5 * dt * k1v, k2v = rhs(delta + 0.5 * dt * k1x, k2x);
    const double k3x = rate + 0.5 * dt * k2v, k3v = rhs(delta + 0.5 * dt * k2x, k3x);
    const double k4x = rate + dt * k3v, k4v = rhs(delta + dt * k3x, k4x);
    const double next = delta + dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    rate += dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    t += dt;
    peak = std::max(peak, next);
    if (next <= 0.0) return {t - dt + dt * delta / (delta - next), -rate, peak};
    delta = next;
  }
}

// The tangential force of a contact pressed to `delta` (at rest along n = z) whose
// partner slides by at velocity `slip`, one step of dt; u is its history.
template <class C>
Vec4 tangential_step(const dem::LoopMaterial& m, double delta, const Vec4& slip, Vec4& u,
                     double dt) {
  dem::ContactInput<ScalarMath> in{};
  in.n = Vec4(0, 0, 1, 0);
  in.delta = delta;
  in.d = 1.0;
  in.v_rel = slip;
  in.spin = Vec4::Zero();
  in.m_eff = 0.5;
  dem::ContactHistory<ScalarMath> h{u, Vec4::Zero()};
  const dem::ContactResult<ScalarMath> r = C::template evaluate<ScalarMath>(in, m, h, dt);
  u = h.u;
  return r.force - r.normal;
}

}  // namespace

// The linear law is the damped oscillator m_eff delta'' = -k_n delta - gamma_n m_eff delta':
// contact time pi / sqrt(k_n/m_eff - gamma_n^2/4) (Eq. 10), restitution exp(-gamma_n t_c / 2)
// (Eq. 9), peak overlap (v/w) exp(-gamma_n t_p / 2) sin(w t_p) at tan(w t_p) = 2 w / gamma_n.
// Tolerance: the scheme's error is first order in dt (the damping sees the half-step
// velocity): 1.7e-4 in e at t_c/4000 for e = 0.5; at t_c/20000 a relative 1e-4 holds with a
// margin of 3, while a damping without m_eff or a missing half kick is off by percents.
TEST(DemContactEvaluator, LinearNormalGivesTheDampedOscillatorsRestitutionAndContactTime) {
  for (double e : {1.0, 0.9, 0.5}) {
    const double m_eff = 0.5;
    const double gamma = e < 1.0 ? dem::damping_for_restitution(e, kKn, m_eff) : 0.0;
    const double tc = dem::linear_contact_time(kKn, gamma, m_eff);
    const Collision c = evaluator_collision<ContactOf<dem::LinearNormal>>(material(gamma, 0.0),
                                                                          m_eff, 1.0, tc / 20000);
    const double w = std::sqrt(kKn / m_eff - 0.25 * gamma * gamma);
    const double tp = std::atan2(2.0 * w, gamma) / w;
    const double peak = std::exp(-0.5 * gamma * tp) * std::sin(w * tp) / w;
    EXPECT_NEAR(c.contact_time / tc, 1.0, 1e-4) << "e = " << e;
    EXPECT_NEAR(c.restitution / e, 1.0, 1e-4) << "e = " << e;
    EXPECT_NEAR(c.peak_overlap / peak, 1.0, 1e-4) << "e = " << e;
  }
}

// Undamped Hertz, F = k_n delta^(3/2) / sqrt(d): peak overlap (5 m_eff v^2 sqrt(d) / 4 k_n)^(2/5)
// from energy, duration 2.9432 delta_max / v (model.hpp), restitution 1. Damped, against a
// Runge-Kutta integration of the same equation at a 10 times finer step (its own error
// ~ (dt)^4, negligible). Tolerances as for the linear law (same scheme, same dt / t_c).
TEST(DemContactEvaluator, HertzNormalLastsTheHertzContactTimeAndMatchesAFineIntegration) {
  const double m_eff = 0.5, d = 1.0;
  const double tc = dem::hertz_contact_time(kKn, d, m_eff, 1.0);
  using Hertz = ContactOf<dem::HertzNormal>;
  const Collision elastic = evaluator_collision<Hertz>(material(0.0, 0.0), m_eff, d, tc / 20000);
  const double peak = std::pow(1.25 * m_eff * std::sqrt(d) / kKn, 0.4);
  EXPECT_NEAR(elastic.contact_time / tc, 1.0, 1e-4);
  EXPECT_NEAR(elastic.peak_overlap / peak, 1.0, 1e-4);
  EXPECT_NEAR(elastic.restitution, 1.0, 1e-4);

  const dem::ContactMaterial damped = material(400.0, 0.0);
  const Collision by_evaluator = evaluator_collision<Hertz>(damped, m_eff, d, tc / 20000);
  const Collision fine = hertz_by_runge_kutta(damped, m_eff, d, tc / 200000);
  EXPECT_LT(fine.restitution, 0.9);  // the damping matters at this gamma_n
  EXPECT_NEAR(by_evaluator.contact_time / fine.contact_time, 1.0, 1e-4);
  EXPECT_NEAR(by_evaluator.restitution / fine.restitution, 1.0, 1e-4);
}

// A contact pressed to a fixed overlap (no normal motion) with its partner sliding by at a
// constant speed: while it sticks, F_t = -(k_t u + gamma_t m_eff v_t) with u = v_t t; from
// the step the trial force passes mu |F_n| on, |F_t| = mu |F_n| exactly (up to rounding);
// reversed, it unloads elastically: the next step's force is the capped one plus
// k_t v dt + 2 gamma_t m_eff v, back inside the cone.
TEST(DemContactEvaluator, TangentialSpringSticksThenSlidesAtMuTimesTheNormalForce) {
  for (bool hertz : {false, true}) {
    const dem::ContactMaterial mat = material(40.0, 0.5);
    const dem::LoopMaterial m = dem::loop_material(mat);
    const double delta = 1e-3, dt = 1e-5, v = 0.2, m_eff = 0.5;
    const double f = hertz ? std::sqrt(delta) : 1.0;  // d = 1
    const double cap = mat.mu * f * mat.kn * delta;
    Vec4 u = Vec4::Zero();
    int stuck_steps = 0;
    Vec4 ft;
    for (int k = 1; k <= 4000; ++k) {
      ft = hertz ? tangential_step<ContactOf<dem::HertzNormal, dem::CoulombSpring>>(
                       m, delta, Vec4(v, 0, 0, 0), u, dt)
                 : tangential_step<ContactOf<dem::LinearNormal, dem::CoulombSpring>>(
                       m, delta, Vec4(v, 0, 0, 0), u, dt);
      const double trial = f * (mat.kt * v * k * dt + mat.gamma_t * m_eff * v);
      if (trial <= cap) {
        ++stuck_steps;
        EXPECT_NEAR(-ft[0], trial, 1e-9 * cap) << "step " << k;
      } else {
        EXPECT_NEAR(ft.norm() / cap, 1.0, 1e-12) << "step " << k;
      }
      EXPECT_EQ(ft[1], 0.0);
    }
    // The step where sliding starts, from the analytic trial force.
    const int analytic_stuck =
        static_cast<int>(std::floor((cap / f - mat.gamma_t * m_eff * v) / (mat.kt * v * dt)));
    EXPECT_EQ(stuck_steps, analytic_stuck) << "hertz " << hertz;
    const Vec4 capped = ft;
    const Vec4 back = hertz ? tangential_step<ContactOf<dem::HertzNormal, dem::CoulombSpring>>(
                                  m, delta, Vec4(-v, 0, 0, 0), u, dt)
                            : tangential_step<ContactOf<dem::LinearNormal, dem::CoulombSpring>>(
                                  m, delta, Vec4(-v, 0, 0, 0), u, dt);
    EXPECT_NEAR(back[0], capped[0] + f * (mat.kt * v * dt + 2.0 * mat.gamma_t * m_eff * v),
                1e-9 * cap);
  }
}

// The rolling spring alone: a contact pressed by F_n = k_n delta, its bodies turning against
// each other at a constant rate w about a tangent axis: the torque is -k_r w t (k_r =
// k_t R_eff^2) until it reaches mu_r R_eff |F_n|, then stays there; a turn about
// the normal (twisting) is resisted alike.
TEST(DemContactEvaluator, RollingSpringTurnsUntilItsCapThenHoldsIt) {
  const dem::ContactMaterial mat = material(0.0, 0.5, 0.2);
  const dem::LoopMaterial m = dem::loop_material(mat);
  using Rolling = ContactOf<dem::LinearNormal, dem::CoulombSpring, dem::RollingSpring, true>;
  const double delta = 1e-3, dt = 1e-5, w = 0.3, r_eff = 0.25;
  const double kr = 2.0 / 7.0 * kKn * r_eff * r_eff;
  const double cap = 0.2 * r_eff * kKn * delta;
  const auto torque_after = [&](int steps, const Vec4& turn) {
    dem::ContactHistory<ScalarMath> h{Vec4::Zero(), Vec4::Zero()};
    dem::ContactInput<ScalarMath> in{};
    in.n = Vec4(0, 0, 1, 0);
    in.delta = delta;
    in.d = 1.0;
    in.v_rel = Vec4::Zero();
    in.spin = Vec4::Zero();
    in.m_eff = 0.5;
    in.w_rel = turn;
    in.r_eff = r_eff;
    Vec4 roll = Vec4::Zero();
    for (int k = 0; k < steps; ++k) roll = Rolling::evaluate<ScalarMath>(in, m, h, dt).roll;
    return roll;
  };
  const int elastic_steps = static_cast<int>(cap / (kr * w * dt));
  const Vec4 early = torque_after(elastic_steps / 2, Vec4(0, w, 0, 0));
  EXPECT_NEAR(early[1], -kr * w * dt * (elastic_steps / 2), 1e-9 * cap);
  const Vec4 late = torque_after(3 * elastic_steps, Vec4(0, w, 0, 0));
  EXPECT_NEAR(late.norm() / cap, 1.0, 1e-12);
  EXPECT_LT(late[1], 0.0);
  const Vec4 twisting = torque_after(elastic_steps / 2, Vec4(0, 0, w, 0));
  EXPECT_NEAR(twisting[2], -kr * w * dt * (elastic_steps / 2), 1e-9 * cap);
  EXPECT_EQ(twisting[1], 0.0);
}

namespace {

// Random contacts, one per lane: the pair loop's lanes and the wall arithmetic evaluate
// each over 40 steps (their histories carried), sliding and sticking, and must agree.
template <class C>
void expect_lanes_match_scalar() {
  constexpr int W = dem::lanes::kWidth;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  dem::ContactInput<LaneMath> lane{};
  dem::ContactInput<ScalarMath> scalar[W];
  dem::ContactHistory<LaneMath> lane_h{};
  dem::ContactHistory<ScalarMath> scalar_h[W];
  const dem::LoopMaterial m = dem::loop_material(material(40.0, 0.3, 0.1));
  using dem::lanes::splat;
  const dem::MaterialOf<dem::lanes::Reals> lane_m{
      splat(m.kn), splat(m.kt),     splat(m.gamma_n), splat(m.gamma_t),
      splat(m.mu), splat(m.inv_kt), splat(m.mu_roll), splat(m.k_roll)};
  const auto set = [&](dem::lanes::Vec& v, Vec4& s, int l, const Vec4& x) {
    v.x[l] = x[0];
    v.y[l] = x[1];
    v.z[l] = x[2];
    s = x;
  };
  for (int l = 0; l < W; ++l) {
    const Vec4 n = Vec4(unit(rng), unit(rng), unit(rng), 0).normalized();
    dem::ContactInput<ScalarMath>& s = scalar[l];
    set(lane.n, s.n, l, n);
    set(lane.v_rel, s.v_rel, l, Vec4(unit(rng), unit(rng), unit(rng), 0));
    set(lane.spin, s.spin, l, Vec4(unit(rng), unit(rng), unit(rng), 0));
    set(lane.w_rel, s.w_rel, l, Vec4(unit(rng), unit(rng), unit(rng), 0));
    lane.delta[l] = s.delta = 1e-3 * (1.5 + unit(rng));
    lane.d[l] = s.d = 1.0 + 0.5 * unit(rng);
    lane.m_eff[l] = s.m_eff = 0.5 + 0.3 * unit(rng);
    lane.r_eff[l] = s.r_eff = 0.25 + 0.1 * unit(rng);
    set(lane_h.u, scalar_h[l].u, l, Vec4::Zero());
    set(lane_h.theta, scalar_h[l].theta, l, Vec4::Zero());
  }
  const double dt = 1e-4;
  for (int step = 0; step < 40; ++step) {
    const dem::ContactResult<LaneMath> r =
        C::template evaluate<LaneMath>(lane, lane_m, lane_h, dem::lanes::splat(dt));
    for (int l = 0; l < W; ++l) {
      const dem::ContactResult<ScalarMath> s =
          C::template evaluate<ScalarMath>(scalar[l], m, scalar_h[l], dt);
      const auto expect_same = [&](const dem::lanes::Vec& v, const Vec4& x, const char* what) {
        // Rounding only: the lanes may fuse a multiply and an add that the 4-vectors do not
        // (and sum a dot product in another order), 1e-16 relative per operation.
        const double scale = 1e-12 * std::max(1.0, x.norm());
        EXPECT_NEAR(v.x[l], x[0], scale) << what << " lane " << l << " step " << step;
        EXPECT_NEAR(v.y[l], x[1], scale) << what << " lane " << l << " step " << step;
        EXPECT_NEAR(v.z[l], x[2], scale) << what << " lane " << l << " step " << step;
      };
      expect_same(r.force, s.force, "force");
      if constexpr (C::kFriction) {
        expect_same(r.c, s.c, "n x F_t");
        expect_same(lane_h.u, scalar_h[l].u, "u");
      }
      if constexpr (C::kRolling) {
        expect_same(r.roll, s.roll, "rolling torque");
        expect_same(lane_h.theta, scalar_h[l].theta, "theta");
      }
    }
  }
}

}  // namespace

TEST(DemContactEvaluator, EveryCombinationGivesThePairLanesTheWallsNumbers) {
  using dem::CoulombSpring;
  using dem::HertzNormal;
  using dem::LinearNormal;
  using dem::NoFriction;
  using dem::NoRolling;
  using dem::RollingSpring;
  expect_lanes_match_scalar<ContactOf<LinearNormal>>();
  expect_lanes_match_scalar<ContactOf<LinearNormal, CoulombSpring>>();
  expect_lanes_match_scalar<ContactOf<LinearNormal, CoulombSpring, NoRolling, true>>();
  expect_lanes_match_scalar<ContactOf<LinearNormal, CoulombSpring, RollingSpring, true>>();
  expect_lanes_match_scalar<ContactOf<HertzNormal>>();
  expect_lanes_match_scalar<ContactOf<HertzNormal, CoulombSpring>>();
  expect_lanes_match_scalar<ContactOf<HertzNormal, CoulombSpring, NoRolling, true>>();
  expect_lanes_match_scalar<ContactOf<HertzNormal, CoulombSpring, RollingSpring, true>>();
}

// The parts' energies and durations, summed by the Contact: each part present adds its own.
TEST(DemContactEvaluator, PartsAddTheirEnergiesAndDurations) {
  const dem::ContactMaterial m = material(0.0, 0.5, 0.2);
  const Vector3d u(1e-4, 0, 0), theta(0, 2e-3, 0);
  const double delta = 1e-3, d = 1.0, r_eff = 0.25;
  using Plain = ContactOf<dem::LinearNormal>;
  using Rolling = ContactOf<dem::LinearNormal, dem::CoulombSpring, dem::RollingSpring, true>;
  const dem::ContactEnergy plain = Plain::energy(m, delta, d, r_eff, u, theta);
  const dem::ContactEnergy all = Rolling::energy(m, delta, d, r_eff, u, theta);
  EXPECT_DOUBLE_EQ(plain.normal, 0.5 * kKn * delta * delta);
  EXPECT_EQ(plain.tangential, 0.0);
  EXPECT_EQ(plain.rolling, 0.0);
  EXPECT_DOUBLE_EQ(all.tangential, 0.5 * m.kt * 1e-8);
  EXPECT_DOUBLE_EQ(all.rolling, 0.5 * m.kt * r_eff * r_eff * 4e-6);
  // Two unit spheres: the rolling spring's half period pi sqrt(I_eff / k_r), I_eff = 0.05
  // (I = 0.1 each), k_r = k_t / 16, is 2.4 times the normal contact's: the normal law decides.
  const dem::TwoBodies spheres{0.5, 0.05, 1.0, 0.25, 1.0};
  const double normal_tc = dem::linear_contact_time(kKn, 0.0, 0.5);
  EXPECT_DOUBLE_EQ(Plain::contact_time(m, spheres), normal_tc);
  EXPECT_DOUBLE_EQ(Rolling::contact_time(m, spheres), normal_tc);
  // A sphere on a wall whose tangential (so rolling) spring is as stiff as the normal one:
  // the rolling spring's pi sqrt(0.1 / (k_n / 4)) is shorter than pi sqrt(1 / k_n), and the
  // tangential spring's, on m_t = 2/7 m_eff, shorter still: pi sqrt(2/7 / k_n) decides.
  dem::ContactMaterial stiff = m;
  stiff.kt = kKn;
  const dem::TwoBodies on_wall{1.0, 0.1, 1.0, 0.5, 1.0};
  const double wall_tc = dem::linear_contact_time(kKn, 0.0, 1.0);
  EXPECT_LT(std::numbers::pi * std::sqrt(0.1 / (0.25 * kKn)), wall_tc);
  EXPECT_DOUBLE_EQ(Rolling::contact_time(stiff, on_wall), wall_tc * std::sqrt(2.0 / 7.0));
  EXPECT_DOUBLE_EQ(Plain::contact_time(stiff, on_wall), wall_tc);
  // The tangential spring alone, and without friction none.
  using TangentialOnly = ContactOf<dem::LinearNormal, dem::CoulombSpring>;
  EXPECT_DOUBLE_EQ(TangentialOnly::contact_time(stiff, on_wall), wall_tc * std::sqrt(2.0 / 7.0));
  // k_t = 500 k_n (the probe's 1e8 against 2e5) went unchecked: t_c is now the spring's.
  stiff.kt = 500.0 * kKn;
  EXPECT_DOUBLE_EQ(TangentialOnly::contact_time(stiff, on_wall),
                   wall_tc * std::sqrt(2.0 / 7.0 / 500.0));
  EXPECT_DOUBLE_EQ(TangentialOnly::contact_time(material(0.0, 0.0), on_wall), wall_tc);
  // The spring's time is its own oscillator's, damped by its own dashpot (rate 7/2 gamma_t
  // on 2/7 m_eff), whatever the normal dashpot (it was scaled from the damped normal time).
  dem::ContactMaterial damped = material(100.0, 0.5);
  damped.kt = kKn;
  const double tangential = dem::linear_contact_time(kKn, 3.5 * 50.0, 2.0 / 7.0);
  EXPECT_LT(tangential, dem::linear_contact_time(kKn, 100.0, 1.0));
  EXPECT_DOUBLE_EQ(TangentialOnly::contact_time(damped, on_wall), tangential);
  damped.gamma_n = 400.0;
  EXPECT_DOUBLE_EQ(TangentialOnly::contact_time(damped, on_wall), tangential);
  // Without rolling friction the rolling part has no duration.
  EXPECT_DOUBLE_EQ(Rolling::contact_time(material(0.0, 0.5), on_wall),
                   dem::linear_contact_time(kKn, 0.0, 1.0));
}
