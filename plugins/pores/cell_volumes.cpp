#include "cell_volumes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "power_volumes.hpp"
#include "regular_cells.hpp"
#include "wall_mirrors.hpp"

namespace granpipe::pores {

namespace {

// Mirrors are made of the points within this many mean radii of a wall, a depth doubled
// while a cell still reaches beyond a wall (then it lacks the mirror of a farther point).
constexpr double kFirstMirrorDepth = 4.0;

// The depth beyond which every point is mirrored.
double deepest(const Frame& frame, const std::vector<PlaneWall>& walls) {
  double depth = 0.0;
  for (const PlaneWall& w : walls) {
    const auto& x = frame.position().col(w.axis);
    depth =
        std::max({depth, std::abs(x.maxCoeff() - w.position), std::abs(x.minCoeff() - w.position)});
  }
  return depth;
}

bool reaches_beyond_a_wall(const PowerVolumes& v, const Centres& centres) {
  return std::any_of(centres.primary.begin(), centres.primary.end(),
                     [&](std::uint32_t p) { return (v.flags[p] & kBeyondWall) != 0; });
}

// The particles' volumes from their primary points.
CellVolumes per_particle(const PowerVolumes& v, const Centres& centres) {
  CellVolumes out;
  out.volume.resize(static_cast<Eigen::Index>(centres.primary.size()));
  for (std::size_t k = 0; k < centres.primary.size(); ++k) {
    const std::uint32_t p = centres.primary[k];
    double& volume = out.volume[static_cast<Eigen::Index>(k)];
    if (!(v.flags[p] & kSeen)) {
      volume = 0.0;
      ++out.hidden;
    } else if (v.flags[p] & (kUnbounded | kOutside | kBeyondWall)) {
      volume = std::numeric_limits<double>::quiet_NaN();
      ++out.undefined;
    } else {
      volume = v.volume[p];
      out.skin_needed = std::max(out.skin_needed, v.overshoot[p]);
    }
  }
  return out;
}

// Triangulates the points with mirrors of those within a growing depth of the walls until
// no particle's cell reaches beyond a wall; `measure(mirrors)` adds the mirrors given to
// the triangulation and returns the volumes of all points so far.
template <class Measure>
CellVolumes with_mirrors(const Centres& centres, const Frame& frame, Measure measure) {
  const std::vector<PlaneWall> walls = plane_walls(frame.container);
  const double all = deepest(frame, walls), radius = frame.radius().mean();
  double depth = walls.empty() ? 0.0 : kFirstMirrorDepth * radius;
  PowerVolumes v = measure(wall_mirrors(centres, walls, 0.0, depth));
  while (depth <= all && reaches_beyond_a_wall(v, centres)) {
    v = measure(wall_mirrors(centres, walls, depth, 2.0 * depth));
    depth *= 2.0;
  }
  return per_particle(v, centres);
}

void append(Centres& to, const Centres& more) {
  to.points.insert(to.points.end(), more.points.begin(), more.points.end());
  to.particle.insert(to.particle.end(), more.particle.begin(), more.particle.end());
}

}  // namespace

CellVolumes voronoi_volumes(DelaunayTriangulation& t, const std::vector<DelaunayCell>& cells,
                            const Centres& centres, const Frame& frame, double tolerance) {
  const CellBounds bounds(frame, tolerance);
  if (plane_walls(frame.container).empty()) {
    return per_particle(power_volumes(centres.points, {}, 0.0, cells, bounds), centres);
  }
  Centres all = centres;
  return with_mirrors(centres, frame, [&](const Centres& mirrors) {
    t.insert(mirrors.points);
    append(all, mirrors);
    return power_volumes(all.points, {}, 0.0, t.cells(), bounds);
  });
}

CellVolumes laguerre_volumes(const Centres& centres, const Frame& frame, double tolerance) {
  const CellBounds bounds(frame, tolerance);
  const double largest = frame.radius().maxCoeff();
  const auto weights_of = [&](const Centres& c) {
    std::vector<double> w(c.points.size());
    for (std::size_t k = 0; k < w.size(); ++k) w[k] = std::pow(frame.radius()[c.particle[k]], 2);
    return w;
  };
  Centres all = centres;
  std::vector<double> weights = weights_of(centres);
  RegularTriangulation t(centres.points, weights);
  return with_mirrors(centres, frame, [&](const Centres& mirrors) {
    const std::vector<double> more = weights_of(mirrors);
    t.insert(mirrors.points, more);
    append(all, mirrors);
    weights.insert(weights.end(), more.begin(), more.end());
    return power_volumes(all.points, weights, largest * largest, t.cells(), bounds);
  });
}

}  // namespace granpipe::pores
