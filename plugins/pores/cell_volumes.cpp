#include "cell_volumes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "regular_cells.hpp"
#include "wall_cells.hpp"

namespace granpipe::pores {

namespace {

const std::vector<double> kUnweighted;

bool defined(std::uint8_t flags) {
  return (flags & kSeen) && !(flags & (kUnbounded | kOutside | kBeyondWall));
}

// The particles whose cells the triangulation leaves unbounded or reaching through a wall,
// but those that are outside the open surface or the cylinder even when cut at the walls.
std::vector<std::uint32_t> at_walls(const PowerVolumes& v, const Centres& centres) {
  std::vector<std::uint32_t> rows;
  for (std::uint32_t p : centres.primary) {
    if ((v.flags[p] & (kUnbounded | kBeyondWall)) && !(v.flags[p] & kOutsideWithinWalls))
      rows.push_back(p);
  }
  return rows;
}

// The particles' volumes from their primary points.
CellVolumes per_particle(const PowerVolumes& v, const Centres& centres) {
  CellVolumes out;
  out.volume.resize(static_cast<Eigen::Index>(centres.primary.size()));
  for (std::size_t k = 0; k < centres.primary.size(); ++k) {
    const std::uint32_t p = centres.primary[k];
    double& volume = out.volume[static_cast<Eigen::Index>(k)];
    if (defined(v.flags[p])) {
      volume = v.volume[p];
    } else if (!(v.flags[p] & kSeen)) {
      volume = 0.0;
      ++out.hidden;
    } else {
      volume = std::numeric_limits<double>::quiet_NaN();
      ++out.undefined;
    }
  }
  out.shortfall = shortfall_of_cells(v, centres);
  return out;
}

template <class Cell>
CellVolumes volumes_of(PowerVolumes v, const WeightedPoints& points, const std::vector<Cell>& cells,
                       const Centres& centres, const CellBounds& bounds, int threads) {
  sum_volumes(v, points, cells, threads);
  if (bounds.has_plane_walls())
    cut_at_walls(v, at_walls(v, centres), points, cells, bounds, threads);
  return per_particle(v, centres);
}

}  // namespace

PowerVolumes voronoi_extents(const std::vector<DelaunayCell>& cells,
                             const std::vector<std::uint32_t>& hull, const Centres& centres,
                             const CellBounds& bounds, int threads) {
  return cell_extents(WeightedPoints{centres.points, kUnweighted, 0.0}, cells, hull, bounds,
                      threads);
}

double shortfall_of_cells(const PowerVolumes& extents, const Centres& centres) {
  double shortfall = 0.0;
  for (std::uint32_t p : centres.primary)
    if (defined(extents.flags[p])) shortfall = std::max(shortfall, extents.shortfall[p]);
  return shortfall;
}

CellVolumes voronoi_volumes(PowerVolumes extents, const std::vector<DelaunayCell>& cells,
                            const Centres& centres, const CellBounds& bounds, int threads) {
  return volumes_of(std::move(extents), WeightedPoints{centres.points, kUnweighted, 0.0}, cells,
                    centres, bounds, threads);
}

CellVolumes laguerre_volumes(const Centres& centres, const Frame& frame, const CellBounds& bounds,
                             int threads) {
  std::vector<double> weights(centres.points.size());
  for (std::size_t k = 0; k < weights.size(); ++k)
    weights[k] = std::pow(frame.radius()[centres.particle[k]], 2);
  const double largest = frame.radius().maxCoeff();
  const WeightedPoints points{centres.points, weights, largest * largest};
  RegularTriangulation t(centres.points, weights);
  const std::vector<DualCell> cells = t.cells(threads);
  return volumes_of(cell_extents(points, cells, t.hull(), bounds, threads), points, cells, centres,
                    bounds, threads);
}

}  // namespace granpipe::pores
