#pragma once
// Which pores a measurement counts: all of them, or those whose centre lies in a box
// inside the container, away from its walls (the paper: 2 R from the walls, 18 R high).
#include <cstdint>
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

// Where the packing ends on one side of an axis (high: 1 for the upper side): the wall
// (moved by the wall offset), the box side along a periodic axis, the outermost particle
// surface at an open side.
double packing_side(const Frame& frame, int axis, int high);

// Nothing for kind All. For Inner, the box container shrunk by `margin` radii from every
// wall (unbounded along periodic axes), its top the container's or, for an open top, the
// highest particle top, and `height` radii high when height > 0. Throws InputError after
// `where` for a cylinder, for a region of no volume or reaching above that top, and for a
// height along a periodic z.
std::optional<Region> pore_region(const Frame& frame, const RegionSettings& settings, double radius,
                                  const std::string& where);

}  // namespace granpipe::pores
