#include "lammps_data_source.hpp"

#include <fstream>

#include "data_file.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/particles_outside.hpp"

namespace granpipe::lammps_data {

namespace {

// The parameter that places a wall (the box's x and y sides hold every particle).
const char* parameter_of(Wall w) {
  if (w == Wall::CylinderSide) return "cylinder_radius";
  return w == Wall::ZLow ? "base" : "top";
}

}  // namespace

Schema schema() {
  Schema s;
  s.path("file", std::nullopt, "LAMMPS data file (atom_style sphere)");
  s.real("cylinder_radius", 0.0, "radius of the vertical cylinder the particles are in (0: none)")
      .min(0.0)
      .unit("length");
  s.real("base", 0.0, "height of the flat base").unit("length");
  s.real("top", 100.0, "height of the container's open top").unit("length");
  return s;
}

LammpsDataSource::LammpsDataSource(const PluginContext& ctx) {
  const std::string file = ctx.params.string("file");
  std::ifstream in(file);
  if (!in) throw InputError(ctx.param("file") + ": cannot read " + file);
  frame_ = read_atoms(in, file);
  if (frame_.size() == 0) throw InputError(file + ": expected atoms, got none");
  frame_.check(file);
  const double r = ctx.params.real("cylinder_radius"), base = ctx.params.real("base");
  const double top = ctx.params.real("top");
  if (!(top > base))
    throw InputError(ctx.param("top") + ": expected a height above base, got " +
                     format_number(top));
  const double half =
      r > 0 ? r : (frame_.position().leftCols(2).abs().maxCoeff() + frame_.radius().maxCoeff());
  frame_.container = Container::open_top_box(3, Eigen::Vector3d(-half, -half, base),
                                             Eigen::Vector3d(half, half, top));
  if (r > 0) {
    frame_.container.shape = ContainerShape::Cylinder;
    frame_.container.cylinder_radius = r;
  }
  if (const auto out = first_particle_outside(frame_, kWallTolerance)) {
    throw InputError(file + ": atom " + std::to_string(frame_.id()[out->particle]) + " " +
                     describe(frame_, *out, kWallTolerance) + " (the container of " +
                     ctx.param(parameter_of(out->wall)) + ")");
  }
}

bool LammpsDataSource::next(Frame& frame) {
  if (done_) return false;
  frame = frame_;
  done_ = true;
  return true;
}

}  // namespace granpipe::lammps_data
