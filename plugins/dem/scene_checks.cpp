#include "scene_checks.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "contact_evaluator.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "overlap_limit.hpp"

namespace granpipe::dem {

namespace {

// The deepest overlap of a sphere against a wall, as a fraction of its radius, and which.
struct Deepest {
  double fraction = 0.0;
  double depth = 0.0;
  int species = -1;
  double radius = 0.0;
  Wall wall = Wall::Count;
};

// How squarely wall `slot` faces a push along the unit vector `along`: the component of
// `along` on its normal (a drive along z hits the base and a lid, not the cylinder). A
// drive pushes both ways; gravity one way, onto the walls it points at (gravity up was
// checked against the base, and refused where the top is open).
enum class Push { BothWays, OneWay };

double facing(const WallSet& walls, int slot, const Eigen::Vector3d& along, Push push) {
  if (slot < static_cast<int>(walls.planes().size())) {
    const PlaneWall& w = walls.planes()[static_cast<std::size_t>(slot)];
    const double onto = -along[w.axis] * w.sign;  // > 0: towards the wall
    return push == Push::BothWays ? std::abs(onto) : std::max(0.0, onto);
  }
  return std::hypot(along[0], along[1]);
}

// overlap(material, mass, radius, scale): the overlap of one sphere against one wall, the
// push scaled by how squarely the wall faces it. Both checks' overlaps grow with the radius
// faster than the radius does, so the largest sphere of each species decides. Fixed
// species are held by the container and skipped.
Deepest deepest_against_walls(
    const Scene& s, const Eigen::Vector3d& along, Push push,
    const std::function<double(const ContactMaterial&, double, double, double)>& overlap) {
  std::vector<double> largest(static_cast<std::size_t>(s.model.species()), 0.0);
  for (Eigen::Index i = 0; i < s.start.radius.size(); ++i) {
    double& r = largest[static_cast<std::size_t>(s.start.species[i])];
    r = std::max(r, s.start.radius[i]);
  }
  Deepest deepest;
  for (int a = 0; a < s.model.species(); ++a) {
    const double r = largest[static_cast<std::size_t>(a)];
    if (r == 0.0 || s.model.is_fixed(a)) continue;
    for (int slot = 0; slot < s.walls.count(); ++slot) {
      const double scale = facing(s.walls, slot, along, push);
      if (scale == 0.0) continue;
      const Wall w = s.walls.wall_of_slot(slot);
      const double depth = overlap(s.model.with_wall(w, a), s.model.sphere_mass(a, r), r, scale);
      if (depth / r > deepest.fraction) deepest = {depth / r, depth, a, r, w};
    }
  }
  return deepest;
}

// "a sphere of species 0 (radius 0.5) hit by wall z_low 0.2 deep (40 % of its radius; a
// sound run stays within 30 %)"
std::string described(const Deepest& d, const std::string& how) {
  return "a sphere of species " + std::to_string(d.species) + " (radius " +
         format_number(d.radius) + ") " + how + " wall " + to_string(d.wall) + " " +
         format_number(d.depth, 3) + " deep (" + format_number(100.0 * d.fraction, 3) +
         " % of its radius; a sound run stays within " +
         format_number(100.0 * kMaxOverlapFraction) + " %)";
}

void check_steps_per_period(const PluginContext& ctx, const Drive& drive, double dt) {
  const double steps = 2.0 * std::numbers::pi / (drive.angular_frequency * dt);
  // Rounding through 2 pi f: frequency 100 at dt 2e-4 gave 49.999... steps, refused as
  // "50 steps ... expected at least 50".
  if (steps >= kMinStepsPerPeriod * (1.0 - 1e-12)) return;
  const double f = drive.angular_frequency / (2.0 * std::numbers::pi);
  throw InputError(ctx.param("drive.frequency") + ": " + format_number(f) + " gives " +
                   format_number(steps, 3) + " steps of dt = " + format_number(dt) +
                   " per period: expected at least " + format_number(kMinStepsPerPeriod) +
                   " (frequency <= " + format_number(1.0 / (kMinStepsPerPeriod * dt), 3) + ")");
}

}  // namespace

void check_drive(const PluginContext& ctx, const Scene& scene, const Drive& drive, double dt) {
  if (!drive.moves()) return;
  check_steps_per_period(ctx, drive, dt);
  // The undamped overlap of a sphere hit at speed v (d = 2a for a wall).
  const double peak = std::abs(drive.amplitude * drive.angular_frequency);
  if (!std::isfinite(peak)) {  // the bound below was then "A 2 pi f <= -nan"
    throw InputError(ctx.param("drive") + ": amplitude " + format_number(drive.amplitude) +
                     " and frequency " +
                     format_number(drive.angular_frequency / (2.0 * std::numbers::pi)) +
                     ": expected a finite peak wall speed A 2 pi f, got " + format_number(peak));
  }
  const auto [d, exponent] = with_contact_law(scene.law, [&](auto normal) {
    using Normal = decltype(normal);
    const auto hit = [&](const ContactMaterial& m, double mass, double a, double scale) {
      return Normal::impact_overlap(m.kn, mass, peak * scale, 2.0 * a);
    };
    return std::pair(deepest_against_walls(scene, drive.direction, Push::BothWays, hit),
                     Normal::kSpeedPerOverlapExponent);
  });
  if (d.fraction <= kMaxOverlapFraction) return;
  const double v_max = peak * std::pow(kMaxOverlapFraction / d.fraction, exponent);
  throw InputError(
      ctx.param("drive") + ": amplitude " + format_number(drive.amplitude) + " and frequency " +
      format_number(drive.angular_frequency / (2.0 * std::numbers::pi)) +
      " move the walls at up to A 2 pi f = " + format_number(peak, 3) + ", which would press " +
      described(d, "hit by") + ": expected A 2 pi f <= " + format_number(v_max, 3));
}

void check_gravity(const PluginContext& ctx, const Scene& scene, const Eigen::Vector3d& gravity) {
  const double g = gravity.stableNorm();
  if (g == 0.0) return;
  // The deepest overlap at which a sphere rests on a wall under its weight at |g| = g_abs.
  const auto deepest_at = [&](double g_abs) {
    return with_contact_law(scene.law, [&](auto normal) {
      using Normal = decltype(normal);
      const auto rest = [&](const ContactMaterial& m, double mass, double a, double scale) {
        return Normal::rest_overlap(m.kn, mass * g_abs * scale, 2.0 * a);
      };
      return std::pair(deepest_against_walls(scene, gravity / g, Push::OneWay, rest),
                       Normal::kWeightPerOverlapExponent);
    });
  };
  const auto [d, exponent] = deepest_at(g);
  if (d.fraction <= kMaxOverlapFraction) return;
  // Scaled from a unit weight: from g itself, an infinite overlap (g = 1e308) gave |g| <= 0.
  const double g_max = std::pow(kMaxOverlapFraction / deepest_at(1.0).first.fraction, exponent);
  throw InputError(ctx.param("gravity") + ": |g| = " + format_number(g, 3) + " would press " +
                   described(d, "resting on") + ": expected |g| <= " + format_number(g_max, 3));
}

void check_damping(const PluginContext& ctx, const Scene& scene, double background, double air,
                   double dt) {
  const double b = background + air;
  if (b == 0.0) return;
  double lightest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < scene.start.radius.size(); ++i) {
    lightest =
        std::min(lightest, scene.model.sphere_mass(scene.start.species[i], scene.start.radius[i]));
  }
  if (b * dt <= lightest) return;
  throw InputError(ctx.param(air > background ? "air_damping" : "background_damping") +
                   ": expected a drag that takes at least a time step to stop the lightest "
                   "sphere (mass " +
                   format_number(lightest) +
                   "): b + b_air at most m / dt = " + format_number(lightest / dt) + ", got " +
                   format_number(b) + " (b dt / m = " + format_number(b * dt / lightest, 3) + ")");
}

}  // namespace granpipe::dem
