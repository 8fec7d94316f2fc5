// The collision analyzer on hand-made frames of the linear law's exact solution (its
// measures then differ from the analytic values only by the interpolation at the contact's
// ends), and on frames that are not one collision of two spheres in free flight.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "collision_analyzer.hpp"
#include "linear_law.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;

namespace {

constexpr double kKn = 2e5, kGamma = 42.398, kDensity = 1.91, kSpeed = 1.0, kStart = 0.0123;
const double kMass = kDensity * std::numbers::pi / 6.0;  // d = 1

// Two spheres of radius 0.5 on the x axis, `gap` apart (negative: overlapping), sphere 0 on
// the right; `closing` the speed at which the gap shrinks; `touching` puts the pair in the
// contact table.
Frame pair_frame(double time, double gap, double closing, bool touching) {
  Frame f;
  f.resize(2, 3);
  f.radius().setConstant(0.5);
  f.species().setZero();
  f.position() << 5.0 + 0.5 * (1.0 + gap), 5, 5, 5.0 - 0.5 * (1.0 + gap), 5, 5;
  auto& v = f.add("velocity").as<Coordinates>();
  v.setZero();
  v(0, 0) = -0.5 * closing;
  v(1, 0) = 0.5 * closing;
  f.add_contacts(touching ? 1 : 0);
  if (touching) {
    f.contact_i()[0] = 0;
    f.contact_j()[0] = 1;
  }
  f.time = time;
  return f;
}

// The exact linear-law collision: free approach at kSpeed, contact from kStart for t_c,
// free separation at e kSpeed; sampled every `step`.
std::vector<Frame> exact_collision(double step, double until) {
  const double m_eff = kMass / 2.0, omega = std::sqrt(kKn / m_eff - kGamma * kGamma / 4.0);
  const double t_c = std::numbers::pi / omega, e = std::exp(-kGamma * t_c / 2.0);
  std::vector<Frame> frames;
  for (double t = 0.0; t < until; t += step) {
    const double s = t - kStart;
    double overlap = 0.0, rate = 0.0;
    if (s < 0.0) {
      overlap = kSpeed * s;
      rate = kSpeed;
    } else if (s < t_c) {
      const double decay = std::exp(-kGamma * s / 2.0);
      overlap = kSpeed / omega * decay * std::sin(omega * s);
      rate = kSpeed * decay * (std::cos(omega * s) - kGamma / (2.0 * omega) * std::sin(omega * s));
    } else {
      overlap = -e * kSpeed * (s - t_c);
      rate = -e * kSpeed;
    }
    frames.push_back(pair_frame(t, -overlap, rate, overlap > 0.0));
  }
  return frames;
}

std::unique_ptr<test::PluginHarness> context() {
  return test::make_context(collision::schema(), {{"k_n", kKn}, {"gamma_n", kGamma}, {"density", {kDensity}}});
}

Results analyse(const std::vector<Frame>& frames) {
  const auto ctx = context();
  collision::CollisionAnalyzer analyzer(*ctx);
  FrameCache cache;
  for (const Frame& f : frames) analyzer.consume(f, cache);
  Results r;
  analyzer.finish(r);
  return r;
}

// The InputError message of analysing `frames`, or "" when there is none.
std::string refusal(const std::vector<Frame>& frames) {
  try {
    analyse(frames);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Collision, TheLinearLawPredictsEquationTen) {
  const collision::LinearPrediction p = collision::predict_linear(kKn, kGamma, kMass / 2.0, "test");
  const double t_c = std::numbers::pi / std::sqrt(kKn / (kMass / 2.0) - kGamma * kGamma / 4.0);
  EXPECT_NEAR(p.contact_time, t_c, 1e-15);
  EXPECT_NEAR(p.restitution, std::exp(-kGamma * t_c / 2.0), 1e-15);
  EXPECT_NEAR(p.restitution, 0.9, 1e-5);  // Table I's e between small spheres
}

TEST(Collision, TheExactSolutionIsMeasuredWithinTheInterpolation) {
  const double t_c = collision::predict_linear(kKn, kGamma, kMass / 2.0, "test").contact_time;
  const Results r = analyse(exact_collision(0.02 * t_c, 0.03));
  EXPECT_NEAR(r.scalars().at("contact_time_rel_error").value, 0.0, 1e-4);
  EXPECT_NEAR(r.scalars().at("restitution_rel_error").value, 0.0, 1e-12);  // free flight on both sides
  EXPECT_NEAR(r.scalars().at("approach_speed").value, kSpeed, 1e-12);
  EXPECT_NEAR(r.scalars().at("frames_in_contact").value, 50.0, 1.0);
}

TEST(Collision, FramesOfOtherThanTwoSpheresAreRefused) {
  Frame f;
  f.resize(3, 3);
  f.add("velocity");
  f.add_contacts(0);
  EXPECT_EQ(refusal({f}), "frame 0: expected the two spheres of a collision, got 3 particles");
}

TEST(Collision, ASphereTouchingAWallIsRefused) {
  Frame f = pair_frame(0.0, 0.1, 1.0, false);
  f.add_contacts(1);
  f.contact_i()[0] = 1;
  f.contact_j()[0] = partner::wall(Wall::XLow);
  EXPECT_EQ(refusal({f}), "frame 0: expected the spheres in free flight, got sphere 1 touching wall x_low "
                          "(a larger container?)");
}

TEST(Collision, NoContactIsRefused) {
  EXPECT_EQ(refusal({pair_frame(0.0, 0.1, 1.0, false), pair_frame(0.01, 0.09, 1.0, false)}),
            "collision: 2 frames: expected the two spheres to collide, got no contact");
}

TEST(Collision, TouchingInTheFirstFrameIsRefused) {
  EXPECT_EQ(refusal({pair_frame(0.0, -0.001, 1.0, true)}),
            "frame 0: expected the spheres apart in the first frame (the approach before the collision), "
            "got them touching");
}

TEST(Collision, AContactThatHasNotEndedIsRefused) {
  EXPECT_EQ(refusal({pair_frame(0.0, 0.001, 1.0, false), pair_frame(0.01, -0.001, 1.0, true)}),
            "collision: 2 frames: expected the contact to end by the last frame, got the spheres still "
            "touching (a longer duration?)");
}

TEST(Collision, ASecondContactIsRefused) {
  EXPECT_EQ(refusal({pair_frame(0.0, 0.001, 1.0, false), pair_frame(0.01, -0.001, 1.0, true),
                     pair_frame(0.02, 0.001, -1.0, false), pair_frame(0.03, -0.001, 1.0, true)}),
            "frame 3: expected one collision, got a second contact of the pair");
}

TEST(Collision, ASpeciesWithoutADensityIsRefused) {
  Frame f = pair_frame(0.0, 0.1, 1.0, false);
  f.species()[1] = 1;
  EXPECT_EQ(refusal({f}), "params.density: expected a density for species 1 of sphere 1, got 1 densities");
}

TEST(Collision, AnOverdampedPairIsRefused) {
  try {
    collision::predict_linear(1.0, 4.0, 1.0, "collision");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "collision: expected an underdamped pair (k_n/m_eff > gamma_n^2/4), got "
                           "k_n/m_eff = 1 and gamma_n^2/4 = 4");
  }
}
