#include "measure_pores.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "apollonius_vertices.hpp"
#include "cell_bounds.hpp"
#include "cell_volumes.hpp"
#include "delaunay_cells.hpp"
#include "granpipe/deepest_overlap.hpp"
#include "granpipe/errors.hpp"
#include "periodic_images.hpp"
#include "skin.hpp"
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
                       [&](const Eigen::Vector3d& x) { return in_box(r, x); });
}

double shortest_period(const Container& c) {
  double shortest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
    if (c.periodic(a)) shortest = std::min(shortest, c.length(a));
  return shortest;
}

bool has_open_side(const Container& c) {
  for (const auto& sides : c.boundary)
    if (sides[0] == Boundary::Open || sides[1] == Boundary::Open) return true;
  return false;
}

// Skin::wider; throws InputError after `where` when the skin spans the period already.
// Counting the pores under an open top up to the surface is the common cause: the hollows
// of a rough surface have pore spheres as wide as the box, whatever its size.
Skin wider_skin(const Skin& skin, double shortfall, double period, bool open_top_counted,
                const std::string& where) {
  if (skin.bulk >= period) {
    std::ostringstream m;
    m << where << ": expected periodic sides longer than the pores (" << period
      << "), got a pore sphere or a particle's cell wider than the box; ";
    if (open_top_counted) {
      m << "with an open side, the pores of the surface's hollows are counted too: region "
           "inner, a margin below the top, leaves them out";
    } else {
      m << "pores of boxes this small are not computed";
    }
    throw InputError(m.str());
  }
  return skin.wider(shortfall, period);
}

struct TriangulatedPores {
  std::vector<Pore> pores;  // in the primary cell
  long cells = 0, flat_cells = 0, untangent_cells = 0, fifth_sphere_cells = 0;
  long apollonius_vertices = 0;
  CellVolumes volumes;
};

struct Measure {
  const Frame& frame;
  Radii radii;
  double tolerance;
  const std::optional<PoreRegion>& region;
  Region primary;  // each pore once
  int threads;

  double length() const { return tolerance * radii.mean; }
  bool counted(const Eigen::Vector3d& pore_centre) const {
    return !region || region->contains(pore_centre);
  }

  // The pores of the Delaunay cells (circumspheres for equal radii, tangent
  // spheres for unequal ones) in the primary cell, and the particles' cells.
  TriangulatedPores pores_of(std::vector<DelaunayCell>& cells, PowerVolumes extents,
                             const Centres& centres, const CellBounds& bounds) const {
    TriangulatedPores found;
    found.cells = static_cast<long>(cells.size());
    std::vector<Pore> missing;
    const auto may_count = [&](const Eigen::Vector3d& c) {
      return in_box(primary, c) && counted(c);
    };
    if (!radii.equal) {
      const NonPoreCells left_out =
          tangent_cells(cells, centres, frame, radii.mean, may_count, length(), threads);
      found.untangent_cells = count_inside(primary, left_out.untangent);
      found.fifth_sphere_cells = count_inside(primary, left_out.fifth_sphere);
      // Cells with no tangent sphere hide vertices too: a rock-salt crystal, whose cells
      // all have one or none, lost four fifths of its pores when only a fifth sphere
      // called for the lifted triangulation.
      if (!left_out.fifth_sphere_cells.empty() || !left_out.untangent.empty())
        missing = missing_vertices(cells, centres, frame, primary, radii.mean, length());
    }
    MergedPores merged = merge_cells(cells, radii.mean, tolerance, threads);
    found.flat_cells = merged.flat_cells;
    found.pores = std::move(merged.pores);
    for (const Pore& p : missing) found.apollonius_vertices += in_box(primary, p.centre);
    found.pores.insert(found.pores.end(), missing.begin(), missing.end());
    std::erase_if(found.pores, [&](const Pore& p) { return !in_box(primary, p.centre); });
    found.volumes = radii.equal
                        ? voronoi_volumes(std::move(extents), cells, centres, bounds, threads)
                        : laguerre_volumes(centres, frame, bounds, threads);
    return found;
  }

  // How far the sphere of a pore counted, grown by the largest particle radius (the
  // circumsphere of the pore's centres), reaches beyond the images.
  double pore_shortfall(const Eigen::Vector3d& centre, double radius,
                        const CellBounds& bounds) const {
    return counted(centre) ? bounds.periodic_shortfall(centre, radius + radii.largest - radii.mean)
                           : 0.0;
  }

  // How much farther the images must reach for every counted pore's sphere and every
  // cell's orthogonal sphere. Only the pores counted need the skin: the huge cells above
  // an open-topped packing with periodic sides never fit in it, and lie outside a region
  // below the top.
  double shortfall_of(const TriangulatedPores& found, const CellBounds& bounds) const {
    double shortfall = found.volumes.shortfall;
    for (const Pore& p : found.pores)
      shortfall = std::max(shortfall, pore_shortfall(p.centre, p.radius, bounds));
    return shortfall;
  }

  // What shortfall_of will find, from the cells before they are merged and the extents of
  // the Voronoi cells (which stand for the Laguerre cells of unequal radii): cheap enough
  // to settle the skin before the pores and volumes are computed.
  double rough_shortfall(const std::vector<DelaunayCell>& cells, const PowerVolumes& extents,
                         const Centres& centres, const CellBounds& bounds) const {
    double shortfall = shortfall_of_cells(extents, centres);
    for (const DelaunayCell& c : cells) {
      if (!c.flat && in_box(primary, c.centre))
        shortfall = std::max(shortfall, pore_shortfall(c.centre, c.radius, bounds));
    }
    return shortfall;
  }

  // Along periodic sides, the images within a skin that starts at first_skin and widens
  // to what the cells need (a tenth more, and by a quarter at least: what a thin skin
  // measures can be short, its cells near the skin being wrong). The images of a wider
  // skin are added to the triangulation made: the Delaunay triangulation of a set of
  // points is one, whatever the order they come in (CGAL breaks the ties of cospherical
  // points by a symbolic perturbation that depends on the points alone).
  TriangulatedPores triangulated_pores(const std::string& where) const {
    const double period = shortest_period(frame.container);
    const bool periodic = std::isfinite(period);
    Skin skin = first_skin(frame, radii.mean);
    Centres centres = centres_with_images(frame, skin);
    DelaunayTriangulation t(centres, frame, where);
    while (true) {
      const CellBounds bounds(frame, length(), skin);
      std::vector<DelaunayCell> cells = t.cells(length(), threads);
      refuse_close_centres(cells, centres, frame, length(), where);
      PowerVolumes extents = voronoi_extents(cells, t.hull(), centres, bounds, threads);
      double shortfall = periodic ? rough_shortfall(cells, extents, centres, bounds) : 0.0;
      if (shortfall <= 0.0) {
        TriangulatedPores found = pores_of(cells, std::move(extents), centres, bounds);
        shortfall = periodic ? shortfall_of(found, bounds) : 0.0;
        if (shortfall <= 0.0) return found;
      }
      const Skin wider = wider_skin(skin, shortfall, period, has_open_side(frame.container), where);
      const Centres more = images_between(frame, skin, wider);
      t.insert(more.points);
      centres.points.insert(centres.points.end(), more.points.begin(), more.points.end());
      centres.particle.insert(centres.particle.end(), more.particle.begin(), more.particle.end());
      skin = wider;
    }
  }
};

// The region moved down by `shift` along its bounded axes, as the primary cell is: a
// lattice's pores lie exactly on its faces at the default margin, and were counted or not
// as the rounding of their centres fell (64 pores of an SC lattice, 125 with the radii
// scaled by 0.1, 27 with the frame moved by 0.1).
std::optional<PoreRegion> moved_down(std::optional<PoreRegion> region, double shift) {
  if (region) {
    region->box.lo.array() -= shift;
    region->box.hi.array() -= shift;
  }
  return region;
}

}  // namespace

PoreMeasurement measure_pores(const Frame& frame, const std::optional<PoreRegion>& given,
                              double tolerance, const std::string& where, int threads) {
  check_frame(frame, where);
  PoreMeasurement m;
  const Radii radii = radii_of(frame);
  m.radius = radii.mean;
  const std::optional<PoreRegion> region = moved_down(given, tolerance * radii.mean / 2.0);
  const Measure measure{
      frame,  radii, tolerance, region, primary_cell(frame.container, tolerance * radii.mean / 2.0),
      threads};
  TriangulatedPores found = measure.triangulated_pores(where);
  m.cells = found.cells;
  m.flat_cells = found.flat_cells;
  m.untangent_cells = found.untangent_cells;
  m.fifth_sphere_cells = found.fifth_sphere_cells;
  m.apollonius_vertices = found.apollonius_vertices;
  m.in_region.reserve(found.pores.size());
  for (const Pore& p : found.pores) {
    const bool counted = !region || region->contains(p.centre);
    m.in_region.push_back(counted ? 1 : 0);
    if (counted) m.xi.push_back(p.radius / m.radius - 1.0);
  }
  m.pores = std::move(found.pores);
  m.cell_volume = std::move(found.volumes.volume);
  m.undefined_volumes = found.volumes.undefined;
  m.hidden_spheres = found.volumes.hidden;
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    Eigen::Vector3d x;
    for (int a = 0; a < 3; ++a) x[a] = frame.container.wrap(a, frame.position()(k, a));
    m.spheres += !region || region->contains(x) ? 1 : 0;
  }
  return m;
}

PoreMeasurement measure_pores(const Frame& frame, const PoreSettings& settings,
                              const std::string& where) {
  check_frame(frame, where);
  // Deeper, a pore sphere "touching" four spheres is inside some of them, and a Voronoi cell
  // smaller than its sphere gives a local packing fraction above 1 (up to 338 in a random gas).
  refuse_deep_overlap(frame, settings.max_overlap, settings.max_overlap_param,
                      ": pores are the void between spheres that overlap little", where);
  return measure_pores(frame, pore_region(frame, settings.region, radii_of(frame).mean, where),
                       settings.tolerance, where, settings.threads);
}

}  // namespace granpipe::pores
