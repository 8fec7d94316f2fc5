#include "measure_pores.hpp"

#include <sstream>

#include "granpipe/errors.hpp"
#include "merge_cells.hpp"

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
  for (int a = 0; a < 3; ++a) {
    if (frame.container.periodic(a)) {
      throw InputError(where + ": expected a container without periodic sides, got axis " +
                       std::to_string(a) +
                       " periodic (pores across periodic sides are not implemented yet)");
    }
  }
}

// R, when every radius is R within kEqualRadii.
double common_radius(const Frame& frame, const std::string& where) {
  const double small = frame.radius().minCoeff(), large = frame.radius().maxCoeff();
  if (large - small > kEqualRadii * large) {
    std::ostringstream m;
    m << where << ": expected equal radii (within a relative " << kEqualRadii
      << "), got radii from " << small << " to " << large
      << " (pores of unequal spheres are not implemented yet)";
    throw InputError(m.str());
  }
  return frame.radius().mean();
}

bool inside(const Region& r, const Eigen::Vector3d& x) {
  for (int a = 0; a < 3; ++a)
    if (!(x[a] >= r.lo[a] && x[a] < r.hi[a])) return false;
  return true;
}

}  // namespace

PoreMeasurement measure_pores(const Frame& frame, const std::optional<Region>& region,
                              double tolerance, const std::string& where) {
  check_frame(frame, where);
  PoreMeasurement m;
  m.radius = common_radius(frame, where);
  const std::vector<DelaunayCell> cells = delaunay_cells(frame, where);
  const MergedPores merged = merge_cells(cells, m.radius, tolerance);
  m.cells = static_cast<long>(cells.size());
  m.flat_cells = merged.flat_cells;
  for (const Pore& p : merged.pores) {
    if (!region || inside(*region, p.centre)) m.xi.push_back(p.radius / m.radius - 1.0);
  }
  if (!region) {
    m.spheres = frame.size();
  } else {
    for (Eigen::Index k = 0; k < frame.size(); ++k)
      m.spheres += inside(*region, frame.position().row(k).transpose()) ? 1 : 0;
  }
  return m;
}

PoreMeasurement measure_pores(const Frame& frame, const PoreSettings& settings,
                              const std::string& where) {
  check_frame(frame, where);
  return measure_pores(frame,
                       pore_region(frame, settings.region, common_radius(frame, where), where),
                       settings.tolerance, where);
}

}  // namespace granpipe::pores
