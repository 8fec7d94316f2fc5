#pragma once
// How far beyond the periodic sides of a box the images of the particles reach: one width
// in the bulk, and a wider one in bands along the other sides: the hollows of a deposit's
// open top hold the widest cells, and the cells cut at a wall reach farther than those of
// the bulk. A cell is one of the periodic packing when its sphere lies within the skin
// every point inside it has.
#include <Eigen/Core>
#include <array>
#include <limits>

#include "granpipe/frame.hpp"

namespace granpipe::pores {

struct Skin {
  Skin() = default;
  Skin(double uniform) : bulk(uniform), edge(uniform) {}  // NOLINT: one width everywhere

  double bulk = 0.0;
  double edge = 0.0;  // within the bands, at least bulk
  // Per axis and side (1: upper): where the band along that side begins; a point beyond it
  // is in the band. Infinite: no band.
  std::array<std::array<double, 2>, 3> band{{{-kNone, kNone}, {-kNone, kNone}, {-kNone, kNone}}};

  // The width the images of a particle at x reach.
  double at(const Eigen::Vector3d& x) const;
  // The width every point within `reach` of c has: edge when that sphere lies in a band.
  double around(const Eigen::Vector3d& c, double reach) const;
  // Both widths grown by as much: bulk to a tenth more than bulk + shortfall and a quarter
  // more than before at least, neither beyond the period.
  Skin wider(double shortfall, double period) const;

 private:
  static constexpr double kNone = std::numeric_limits<double>::infinity();
};

// The first skin of a frame along its periodic sides (none: 0), `radius` the particles'
// mean: 4 radii in the bulk (enough for a random packing's cells), 10 radii within 24
// radii of an open side (the hollows of a deposit's rough top need about 7.5 radii at 10^5
// spheres, 8 at 10^6; their cells' spheres reach down about twice that) and within 8 radii
// of a wall (the cells cut there need about 4.3 radii at 10^5), where the packing is at
// least three and a half times as deep as the band along its axis. Bands this thin cost few images;
// a skin too thin is widened (measure_pores).
Skin first_skin(const Frame& frame, double radius);

}  // namespace granpipe::pores
