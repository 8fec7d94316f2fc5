#pragma once
// The pores of one frame: each Delaunay cell of the centres (cells of one sphere merged)
// gives the sphere touching its four particles, of radius r = circumradius - R for equal
// spheres, the tangent sphere's for unequal ones; xi = r / R, R the mean radius. Along
// periodic sides the centres are triangulated with their images near the sides, and each
// pore is counted once. The same triangulation gives each particle's Voronoi cell
// (Laguerre cell for unequal radii, from a regular triangulation).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "granpipe/frame.hpp"
#include "granpipe/region.hpp"
#include "merge_cells.hpp"
#include "pore_region.hpp"

namespace granpipe::pores {

// Relative spread of the radii still taken as one radius (radii stored in single
// precision): such frames keep the circumsphere, exact predicates' circumcentre included.
constexpr double kEqualRadii = 1e-6;

struct PoreSettings {
  double tolerance = 1e-9;  // same sphere, flat cell: relative to the particle radius
  RegionSettings region;
  // Deepest overlap of two spheres accepted, over the smaller radius, and the parameter
  // that sets it (named when a frame is refused).
  double max_overlap = 0.05;
  std::string max_overlap_param = "max_overlap";
  int threads = 1;  // the results do not depend on it, to the bit
};

struct PoreMeasurement {
  double radius = 0.0;     // R, the particles' mean radius
  std::vector<double> xi;  // of the pores counted (centre in the region)
  long spheres = 0;        // particle centres in the region
  long cells = 0;          // Delaunay cells, all of them
  long flat_cells = 0;     // of them, left out as flat
  // Of them, left out for want of a tangent sphere (unequal radii), with their circumcentre
  // in the box along periodic axes (not the hull cells of the images).
  long untangent_cells = 0;
  // Of them, left out as their tangent sphere overlaps a fifth sphere (unequal radii), in
  // the box along periodic axes.
  long fifth_sphere_cells = 0;
  // Pores no Delaunay cell gives (unequal radii), found around those cells
  // (apollonius_vertices.hpp), in the box along periodic axes.
  long apollonius_vertices = 0;
  // Every pore found (each once along periodic sides), and whether it is counted.
  std::vector<Pore> pores;
  std::vector<char> in_region;
  // Per particle: the volume of its Voronoi (Laguerre) cell; NaN where undefined (a cell
  // unbounded, or reaching beyond the packing's open surface or a cylinder), 0 for a
  // sphere whose Laguerre cell is empty (hidden by overlapping neighbours).
  Eigen::ArrayXd cell_volume;
  long undefined_volumes = 0;
  long hidden_spheres = 0;
};

// Throws InputError after `where` for a frame the pores cannot be measured on: not 3D,
// fewer than four particles, NaN or infinite coordinates, a periodic box
// narrower than its pores, and the cases of delaunay_cells and pore_region.
PoreMeasurement measure_pores(const Frame& frame, const PoreSettings& settings,
                              const std::string& where);

// With the region given (nothing: every pore and every particle).
PoreMeasurement measure_pores(const Frame& frame, const std::optional<PoreRegion>& region,
                              double tolerance, const std::string& where, int threads = 1);

}  // namespace granpipe::pores
