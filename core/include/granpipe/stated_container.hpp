#pragma once
// The container of a file that records none. LAMMPS data files and dumps hold the particles
// and the simulation box, while the walls live in the input script (fix wall/gran, mesh
// walls): the user states them in the pipeline, with the parameters declared here once for
// every such source, and the particles are checked against them.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "granpipe/container.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/params.hpp"
#include "granpipe/plugin.hpp"

namespace granpipe {

// The overlap with a wall accepted as touching, in radii: settled soft-sphere packings
// press into their walls by up to a few percent of a radius (data-samples: 0.6 % at rest,
// 2.6 % in a shaken bed).
constexpr double kStatedWallTolerance = 0.05;

// Adds cylinder_radius, cylinder_axis, side_walls, base and top to a source's schema.
void declare_stated_container(Schema& s);

class StatedContainer {
 public:
  // Reads the parameters and checks them together (InputError naming one of them).
  explicit StatedContainer(const PluginContext& ctx);

  // A frame's container: the file's box (its extents, its periodic sides, and whatever
  // the source puts on the sides nothing is stated for) with the stated walls in place
  // of its sides: a cylinder or side walls for the x and y sides, the base and the open
  // top for the z sides unless the box is periodic along z. InputError starting with
  // `where` when a stated wall falls on a periodic side.
  Container place(const Container& file_box, const std::string& where) const;

  // The first particle outside its container, as a message starting with "atom <id>":
  // "atom 7 at (1.9, 0, 1), radius 0.5: expected an overlap with the wall cylinder ...
  // (the container of source.params.cylinder_radius)". `file_sides` names what placed the
  // sides no parameter states (e.g. "the dump's BOX BOUNDS, line 6"). A centre more than
  // the largest radius beyond a non-periodic side of `file_box` (the file's own box, whose
  // z sides the base and top replace) is outside too: the code that wrote the file would
  // have lost that particle.
  struct Outside {
    Eigen::Index particle = 0;  // row in the frame
    std::string message;
  };
  std::optional<Outside> first_outside(const Frame& frame, const Container& file_box,
                                       const std::string& file_sides) const;

 private:
  // What placed wall `w`: the parameter's path, or `file_sides`.
  std::string placed_by(Wall w, const std::string& file_sides) const;

  double cylinder_radius_;          // 0: no cylinder
  Eigen::Vector2d cylinder_axis_;   // where the vertical axis crosses the x-y plane
  std::vector<double> side_walls_;  // x_lo, x_hi, y_lo, y_hi, or none
  double base_, top_;
  // The parameters' paths in the pipeline, for messages.
  std::string cylinder_param_, side_walls_param_, base_param_, top_param_;
};

}  // namespace granpipe
