#include "granpipe/stated_container.hpp"

#include "granpipe/format_number.hpp"
#include "granpipe/particles_outside.hpp"

namespace granpipe {

namespace {

const char* axis_name(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }

constexpr double kDefaultBase = 0.0, kDefaultTop = 100.0;

// The box with its non-periodic sides moved out by `margin`.
Container widened(Container box, double margin) {
  for (int a = 0; a < 3; ++a) {
    if (box.periodic(a)) continue;
    box.lo[a] -= margin;
    box.hi[a] += margin;
  }
  return box;
}

}  // namespace

void declare_stated_container(Schema& s) {
  s.real("cylinder_radius", 0.0, "radius of the vertical cylinder the particles are in (0: none)")
      .min(0.0)
      .unit("length");
  s.reals("cylinder_axis", std::vector<double>{0.0, 0.0}, "x and y of the cylinder's vertical axis")
      .length(2)
      .unit("length")
      .only_where("cylinder_radius > 0",
                  [](const Params& p) { return p.real("cylinder_radius") > 0.0; });
  s.reals("side_walls", std::vector<double>{},
          "x_lo, x_hi, y_lo, y_hi of flat side walls ([]: none; not with a cylinder)")
      .unit("length");
  s.real("base", kDefaultBase,
         "height of the flat base (none where the file's box is periodic along z)")
      .unit("length");
  s.real("top", kDefaultTop,
         "height of the container's open top (none where the file's box is periodic along z)")
      .unit("length");
}

StatedContainer::StatedContainer(const PluginContext& ctx)
    : cylinder_radius_(ctx.params.real("cylinder_radius")),
      cylinder_axis_(ctx.params.reals("cylinder_axis")[0], ctx.params.reals("cylinder_axis")[1]),
      side_walls_(ctx.params.reals("side_walls")),
      base_(ctx.params.real("base")),
      top_(ctx.params.real("top")),
      cylinder_param_(ctx.param("cylinder_radius")),
      side_walls_param_(ctx.param("side_walls")),
      base_param_(ctx.param("base")),
      top_param_(ctx.param("top")) {
  if (!(top_ > base_))
    throw InputError(top_param_ + ": expected a height above base, got " + format_number(top_));
  const std::size_t walls = side_walls_.size();
  if (walls != 0 && walls != 4) {
    throw InputError(side_walls_param_ + ": expected [] or [x_lo, x_hi, y_lo, y_hi], got " +
                     std::to_string(walls) + " numbers");
  }
  if (walls == 4 && cylinder_radius_ > 0) {
    throw InputError(side_walls_param_ + ": expected [] in a cylinder (" + cylinder_param_ + " " +
                     format_number(cylinder_radius_) + "), got side walls");
  }
  for (std::size_t a = 0; a < walls / 2; ++a) {
    if (!(side_walls_[2 * a + 1] > side_walls_[2 * a])) {
      throw InputError(side_walls_param_ + ": expected " + axis_name(static_cast<int>(a)) +
                       "_hi above " + axis_name(static_cast<int>(a)) + "_lo, got " +
                       format_number(side_walls_[2 * a]) + " and " +
                       format_number(side_walls_[2 * a + 1]));
    }
  }
}

Container StatedContainer::place(const Container& file_box, const std::string& where) const {
  Container c = file_box;
  const bool cylinder = cylinder_radius_ > 0, walls = !side_walls_.empty();
  for (int a = 0; a < 2 && (cylinder || walls); ++a) {
    if (c.periodic(a)) {
      throw InputError(where + ": " + (cylinder ? cylinder_param_ : side_walls_param_) +
                       ": expected no walls across the periodic " + axis_name(a) +
                       " sides of the box, got " + (cylinder ? "a cylinder" : "side walls"));
    }
    c.lo[a] = walls ? side_walls_[2 * a] : cylinder_axis_[a] - cylinder_radius_;
    c.hi[a] = walls ? side_walls_[2 * a + 1] : cylinder_axis_[a] + cylinder_radius_;
    c.boundary[a] = {Boundary::Wall, Boundary::Wall};
  }
  if (cylinder) {
    c.shape = ContainerShape::Cylinder;
    c.cylinder_radius = cylinder_radius_;
    c.cylinder_center = cylinder_axis_;
  }
  if (c.periodic(2)) {
    // A base or top given for such a file bounded nothing, without a word.
    const bool base_given = base_ != kDefaultBase;
    if (base_given || top_ != kDefaultTop) {
      throw InputError(where + ": " + (base_given ? base_param_ : top_param_) +
                       ": expected its default " +
                       format_number(base_given ? kDefaultBase : kDefaultTop) +
                       " for a box periodic along z (it bounds nothing there), got " +
                       format_number(base_given ? base_ : top_));
    }
  } else {
    c.lo[2] = base_;
    c.hi[2] = top_;
    c.boundary[2] = {Boundary::Wall, Boundary::Open};
  }
  return c;
}

std::string StatedContainer::placed_by(Wall w, const std::string& file_sides) const {
  switch (w) {
    case Wall::CylinderSide:
      return "the container of " + cylinder_param_;
    case Wall::ZLow:
      return "the container of " + base_param_;
    case Wall::ZHigh:
      return "the container of " + top_param_;
    default:
      return side_walls_.empty() ? file_sides : "the container of " + side_walls_param_;
  }
}

std::optional<StatedContainer::Outside> StatedContainer::first_outside(
    const Frame& frame, const Container& file_box, const std::string& file_sides) const {
  auto atom = [&](Eigen::Index k) { return "atom " + std::to_string(frame.id()[k]) + " "; };
  if (const auto out = first_particle_outside(frame, kStatedWallTolerance)) {
    return Outside{out->particle, atom(out->particle) +
                                      describe(frame, *out, kStatedWallTolerance) + " (" +
                                      placed_by(out->wall, file_sides) + ")"};
  }
  // LAMMPS keeps atoms in its box only when it rebuilds its neighbour lists: a dump may
  // hold some a little outside. A radius beyond is far more than that.
  const Container in_file_box = widened(file_box, frame.radius().maxCoeff());
  const auto out = first_particle_outside(frame, in_file_box, kStatedWallTolerance);
  if (!out) return {};
  return Outside{out->particle, atom(out->particle) +
                                    describe(frame, in_file_box, *out, kStatedWallTolerance) +
                                    " (" + file_sides + ")"};
}

}  // namespace granpipe
