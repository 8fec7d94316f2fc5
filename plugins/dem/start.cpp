#include "start.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/start_frame.hpp"
#include "loose_lattice.hpp"
#include "memory_check.hpp"
#include "start_checks.hpp"

namespace granpipe::dem {

namespace {

// A file without radii read as spheres of radius 0.5, and one without species as species
// 0 in a table of several, without a word: the engine has no default for either.
void refuse_missing_columns(const StartFrame& start, int species) {
  if (!start.radii_stored)
    throw InputError(start.where +
                     ": expected radii (a radius element of its particles), got none");
  if (!start.species_stored && species > 1) {
    throw InputError(start.where +
                     ": expected species (a species element of its particles) for a table of " +
                     std::to_string(species) + " species, got none");
  }
}

// The start file's frame, checked as a DEM start.
Start start_from_file(const PluginContext& ctx, StartFrame start, int species) {
  Frame& f = start.frame;
  const std::string& where = start.where;
  refuse_missing_columns(start, species);
  check_memory(where, static_cast<double>(f.size()));
  f.check(where);
  if (f.dim != 3) throw InputError(where + ": expected a 3D frame, got 2D");
  for (int axis = 0; axis < 3; ++axis) {
    if (f.container.periodic(axis)) {
      throw InputError(where + ": container: " + to_string(static_cast<Wall>(2 * axis)) +
                       ": expected a wall or an open side, got a periodic side (the DEM "
                       "engine has no periodic boundaries)");
    }
  }
  check_start_frame(f, where);
  InitialState s;
  s.position = f.position().matrix().transpose();
  s.radius = f.radius();
  s.species = f.species().cast<int>();
  if (f.size() > 0 && s.species.maxCoeff() >= species) {
    throw InputError(ctx.param("species") +
                     ": expected an entry for every species of the start frame (" +
                     std::to_string(std::int64_t{s.species.maxCoeff()} + 1) + "), got " +
                     std::to_string(species));
  }
  if (f.has("velocity")) s.velocity = f.table<double>("velocity").matrix().transpose();
  if (f.has("angular_velocity")) {
    s.angular_velocity = f.table<double>("angular_velocity").matrix().transpose();
  }
  return {std::move(s), f.container, f.id(), where};
}

// The widest cylinder, in small diameters: the lattice's rows and columns are counted in int.
constexpr double kWidestCylinder = 1e6;

// The bed's refusals, each naming the parameter at fault (loose_lattice's own checks can
// only name the bed as a whole).
void check_bed(const PluginContext& ctx) {
  const Params& b = ctx.params.object("bed");
  const double d = b.real("diameter"), jitter = b.real("jitter");
  const auto refuse = [&](const std::string& name, const std::string& expected) {
    throw InputError(ctx.param("bed." + name) + ": expected " + expected + ", got " +
                     format_number(b.real(name)));
  };
  if (!(b.real("spacing") > 1.0 + 2.0 * jitter)) {
    refuse("spacing", "more than 1 + 2 jitter = " + format_number(1.0 + 2.0 * jitter) +
                          " (room for the sideways nudges)");
  }
  // 1e308 put the spheres at z = inf, refused as "particle 1: position z" naming no parameter.
  if (!(b.real("spacing") <= kWidestCylinder)) {
    refuse("spacing", "at most " + format_number(kWidestCylinder) + " small diameters");
  }
  const double narrowest = 2.0 * narrowest_cylinder_radius(0.5 * d, jitter * d);
  if (!(b.real("cylinder_diameter") >= narrowest)) {
    refuse("cylinder_diameter", "at least " + format_number(narrowest) + " (a sphere of diameter " +
                                    format_number(d) + " and its nudge)");
  }
  if (!(b.real("cylinder_diameter") <= kWidestCylinder * d)) {
    refuse("cylinder_diameter", "at most " + format_number(kWidestCylinder * d) + " (" +
                                    format_number(kWidestCylinder) + " small diameters)");
  }
  if (!(b.real("intruder_diameter") < b.real("cylinder_diameter"))) {
    refuse("intruder_diameter",
           "less than cylinder_diameter (" + format_number(b.real("cylinder_diameter")) + ")");
  }
}

// A loose lattice in an open-topped cylinder standing on z = 0 (loose_lattice.hpp).
Start start_from_bed(const PluginContext& ctx, int species) {
  check_bed(ctx);
  const Params& b = ctx.params.object("bed");
  check_memory(ctx.param("bed.small"), static_cast<double>(b.integer("small")));
  const double d = b.real("diameter"), R = 0.5 * b.real("cylinder_diameter");
  if (b.real("intruder_diameter") > 0.0 && species < 2) {
    throw InputError(ctx.param("species") +
                     ": expected a second species for the bed's intruder "
                     "(species 1), got " +
                     std::to_string(species) + " species");
  }
  Start s;
  try {
    s.state = loose_lattice({.count = static_cast<int>(b.integer("small")),
                             .radius = 0.5 * d,
                             .cylinder_radius = R,
                             .spacing = b.real("spacing") * d,
                             .jitter = b.real("jitter") * d,
                             .intruder_radius = 0.5 * b.real("intruder_diameter"),
                             .seed = ctx.seeds.derive("bed").seed()});
  } catch (const InputError& e) {
    throw InputError(ctx.param("bed") + ": " + e.what());
  }
  s.id = IndexArray::LinSpaced(s.state.radius.size(), 0, s.state.radius.size() - 1);
  Container& c = s.container;
  c.shape = ContainerShape::Cylinder;
  c.cylinder_radius = R;
  c.boundary[2] = {Boundary::Wall, Boundary::Open};
  c.lo = Eigen::Vector3d(-R, -R, 0.0);
  c.hi = Eigen::Vector3d(R, R, s.state.position.row(2).maxCoeff() + d);
  return s;
}

}  // namespace

Start start_of(const PluginContext& ctx, int species) {
  std::optional<StartFrame> saved = read_start_frame(ctx);
  const bool bed = ctx.params.object("bed").integer("small") > 0;
  if (saved.has_value() == bed) {
    throw InputError(ctx.params_path + ": expected either initial_file or bed.small > 0, got " +
                     (bed ? "both" : "neither"));
  }
  return saved ? start_from_file(ctx, std::move(*saved), species) : start_from_bed(ctx, species);
}

}  // namespace granpipe::dem
