#pragma once
// Which pores a measurement counts: all of them whose centre lies in the container, or those
// away from its walls (the paper: 2 R from the walls, 18 R high): a box, and in a vertical
// cylinder also within its radius less the margin.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "granpipe/frame.hpp"
#include "granpipe/params.hpp"
#include "granpipe/region.hpp"

namespace granpipe::pores {

enum class RegionKind : std::uint8_t { All, Inner };
inline ChoiceNames<RegionKind> choice_names(RegionKind) {
  return {{"all", RegionKind::All}, {"inner", RegionKind::Inner}};
}

struct RegionSettings {
  RegionKind kind = RegionKind::All;
  double margin = 2.0;  // particle radii from every wall, and below the top
  double height = 0.0;  // particle radii above the region's bottom; 0: up to the top
};

// The inner region: a box, and in a cylinder container a radius about its axis.
struct PoreRegion {
  PoreRegion() = default;
  PoreRegion(const Region& b) : box(b) {}  // NOLINT: a box is a region of its own
  Region box;
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();
  double radius = std::numeric_limits<double>::infinity();  // none in a box container
  // In the half-open box [lo, hi) and strictly within the radius.
  bool contains(const Eigen::Vector3d& x) const;
};

// Whether x lies in the half-open box [lo, hi) of `r`.
bool in_box(const Region& r, const Eigen::Vector3d& x);

// Where the packing ends on one side of an axis (high: 1 for the upper side): the wall
// (moved by the wall offset), the box side along a periodic axis, the outermost particle
// surface at an open side.
double packing_side(const Frame& frame, int axis, int high);

// Nothing for kind All in a container periodic on every side, else the container itself
// (Inner with margin 0). For Inner, the container shrunk by `margin` radii from every wall
// (unbounded along periodic axes; a cylinder's radius too), its top the container's or, for
// an open top, the highest particle top, and `height` radii high when height > 0. Throws
// InputError after `where` for a region of no volume or reaching above that top, and for a
// height along a periodic z.
std::optional<PoreRegion> pore_region(const Frame& frame, const RegionSettings& settings,
                                      double radius, const std::string& where);

}  // namespace granpipe::pores
