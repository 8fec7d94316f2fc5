#include "measure_pores.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "granpipe/errors.hpp"
#include "merge_cells.hpp"
#include "periodic_images.hpp"
#include "tangent_cells.hpp"

namespace granpipe::pores {

namespace {

void check_frame(const Frame& frame, const std::string& where) {
  if (frame.dim != 3) {
    throw InputError(where + ": expected a 3D frame, got " + std::to_string(frame.dim) + "D");
  }
  frame.check(where);
  if (frame.size() < 4) {
    throw InputError(where + ": expected at least 4 particles (a pore touches four), got " +
                     std::to_string(frame.size()));
  }
}

struct Radii {
  double mean = 0.0, largest = 0.0;
  bool equal = true;  // within kEqualRadii
};

Radii radii_of(const Frame& frame) {
  const double small = frame.radius().minCoeff(), large = frame.radius().maxCoeff();
  return {frame.radius().mean(), large, large - small <= kEqualRadii * large};
}

bool inside(const Region& r, const Eigen::Vector3d& x) {
  for (int a = 0; a < 3; ++a)
    if (!(x[a] >= r.lo[a] && x[a] < r.hi[a])) return false;
  return true;
}

// The box along periodic axes, everything along the others: each pore of a periodic
// packing once. The box is moved down by half the merge tolerance: lattices put pores
// exactly on its sides, where rounding would keep both images of a pore, or none.
Region primary_cell(const Container& c, double shift) {
  Region r;
  for (int a = 0; a < 3; ++a) {
    r.lo[a] = c.periodic(a) ? c.lo[a] - shift : -std::numeric_limits<double>::infinity();
    r.hi[a] = c.periodic(a) ? c.hi[a] - shift : std::numeric_limits<double>::infinity();
  }
  return r;
}

long count_inside(const Region& r, const std::vector<Eigen::Vector3d>& points) {
  return std::count_if(points.begin(), points.end(),
                       [&](const Eigen::Vector3d& x) { return inside(r, x); });
}

double shortest_period(const Container& c) {
  double shortest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
    if (c.periodic(a)) shortest = std::min(shortest, c.length(a));
  return shortest;
}

struct TriangulatedPores {
  std::vector<Pore> pores;  // in the primary cell
  long cells = 0, flat_cells = 0, untangent_cells = 0;
};

// The Delaunay cells with their pore spheres (circumspheres for equal radii).
TangentCells pore_cells(const Frame& frame, const Radii& radii, double tolerance, double skin,
                        const std::string& where) {
  const Centres centres = centres_with_images(frame, skin);
  std::vector<DelaunayCell> cells = delaunay_cells(centres, frame, where);
  if (radii.equal) return {std::move(cells), {}};
  return tangent_cells(cells, centres, frame, radii.mean, tolerance * radii.mean);
}

// The pores in the primary cell, from the centres and their images within a skin that
// starts at kFirstSkin radii and doubles until it holds the sphere of every pore found,
// grown by the largest particle radius (the circumsphere of the pore's centres).
TriangulatedPores triangulated_pores(const Frame& frame, const Radii& radii, double tolerance,
                                     const std::optional<Region>& region,
                                     const std::string& where) {
  const double radius = radii.mean, reach = radii.largest - radii.mean;
  constexpr double kFirstSkin = 4.0;
  const Region primary = primary_cell(frame.container, tolerance * radius / 2.0);
  const double period = shortest_period(frame.container);
  const bool periodic = std::isfinite(period);
  double skin = std::min(kFirstSkin * radius, period);
  while (true) {
    const TangentCells cells = pore_cells(frame, radii, tolerance, skin, where);
    MergedPores merged = merge_cells(cells.cells, radius, tolerance);
    TriangulatedPores found{{},
                            static_cast<long>(cells.cells.size() + cells.untangent.size()),
                            merged.flat_cells,
                            count_inside(primary, cells.untangent)};
    bool held = true;
    for (const Pore& p : merged.pores) {
      if (!inside(primary, p.centre)) continue;
      found.pores.push_back(p);
      // Only the pores counted need the skin: the huge cells above an open-topped
      // packing with periodic sides never fit in it, and lie outside a region below the top.
      const bool counted = !region || inside(*region, p.centre);
      held = held && (!periodic || !counted || p.radius + reach <= skin);
    }
    if (held) return found;
    if (skin >= period) {
      std::ostringstream m;
      m << where << ": expected periodic sides longer than the pores (" << period
        << "), got a pore sphere wider than the box; pores of boxes this small are not computed";
      throw InputError(m.str());
    }
    skin = std::min(2.0 * skin, period);
  }
}
}  // namespace

PoreMeasurement measure_pores(const Frame& frame, const std::optional<Region>& region,
                              double tolerance, const std::string& where) {
  check_frame(frame, where);
  PoreMeasurement m;
  const Radii radii = radii_of(frame);
  m.radius = radii.mean;
  const TriangulatedPores found = triangulated_pores(frame, radii, tolerance, region, where);
  m.cells = found.cells;
  m.flat_cells = found.flat_cells;
  m.untangent_cells = found.untangent_cells;
  for (const Pore& p : found.pores) {
    if (!region || inside(*region, p.centre)) m.xi.push_back(p.radius / m.radius - 1.0);
  }
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    Eigen::Vector3d x;
    for (int a = 0; a < 3; ++a) x[a] = frame.container.wrap(a, frame.position()(k, a));
    m.spheres += !region || inside(*region, x) ? 1 : 0;
  }
  return m;
}

PoreMeasurement measure_pores(const Frame& frame, const PoreSettings& settings,
                              const std::string& where) {
  check_frame(frame, where);
  return measure_pores(frame, pore_region(frame, settings.region, radii_of(frame).mean, where),
                       settings.tolerance, where);
}

}  // namespace granpipe::pores
