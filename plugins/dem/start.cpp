#include "start.hpp"

#include <string>

#include "granpipe/errors.hpp"
#include "granpipe/frame_store.hpp"
#include "loose_lattice.hpp"

namespace granpipe::dem {

namespace {

// Frame `index` of the start file (-1: its last).
Start start_from_file(const PluginContext& ctx, int species) {
  FrameReader reader(ctx.params.string("initial_file"));
  const std::int64_t index = ctx.params.integer("initial_frame");
  const long frames = reader.frames();
  if (frames == 0 || index >= frames) {
    throw InputError(ctx.param("initial_frame") + ": expected a frame of " + reader.info().path +
                     " (it holds " + std::to_string(frames) + "), got " + std::to_string(index));
  }
  Frame f = reader.read(index < 0 ? frames - 1 : static_cast<long>(index));
  f.check(reader.info().path + ": frame " + std::to_string(index));
  if (f.dim != 3) throw InputError(ctx.param("initial_file") + ": expected a 3D frame, got 2D");
  InitialState s;
  s.position = f.position().matrix().transpose();
  s.radius = f.radius();
  s.species = f.species().cast<int>();
  if (f.size() > 0 && s.species.maxCoeff() >= species) {
    throw InputError(ctx.param("species") + ": expected an entry for every species of the start frame (" +
                     std::to_string(s.species.maxCoeff() + 1) + "), got " + std::to_string(species));
  }
  if (f.has("velocity")) s.velocity = f.table<double>("velocity").matrix().transpose();
  if (f.has("angular_velocity")) {
    s.angular_velocity = f.table<double>("angular_velocity").matrix().transpose();
  }
  return {std::move(s), f.container};
}

// A loose lattice in an open-topped cylinder standing on z = 0 (loose_lattice.hpp).
Start start_from_bed(const PluginContext& ctx, int species) {
  const Params& b = ctx.params.object("bed");
  const double d = b.real("diameter"), R = 0.5 * b.real("cylinder_diameter");
  if (b.real("intruder_diameter") > 0.0 && species < 2) {
    throw InputError(ctx.param("species") + ": expected a second species for the bed's intruder "
                     "(species 1), got " + std::to_string(species) + " species");
  }
  Start s;
  try {
    s.state = loose_lattice({.count = static_cast<int>(b.integer("small")), .radius = 0.5 * d,
                             .cylinder_radius = R, .spacing = b.real("spacing") * d,
                             .jitter = b.real("jitter") * d,
                             .intruder_radius = 0.5 * b.real("intruder_diameter"),
                             .seed = ctx.seeds.derive("bed").seed()});
  } catch (const InputError& e) {
    throw InputError(ctx.param("bed") + ": " + e.what());
  }
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
  const bool file = !ctx.params.string("initial_file").empty();
  const bool bed = ctx.params.object("bed").integer("small") > 0;
  if (file == bed) {
    throw InputError(ctx.params_path + ": expected either initial_file or bed.small > 0, got " +
                     (file ? "both" : "neither"));
  }
  return file ? start_from_file(ctx, species) : start_from_bed(ctx, species);
}

}  // namespace granpipe::dem
