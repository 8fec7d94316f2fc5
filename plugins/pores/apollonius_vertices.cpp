#include "apollonius_vertices.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "lifted_vertices.hpp"
#include "pore_region.hpp"
#include "sphere_grid.hpp"
#include "tangent_sphere.hpp"

namespace granpipe::pores {

namespace {

using Quadruple = std::array<std::uint32_t, 4>;  // sorted point rows

Quadruple sorted(Quadruple q) {
  std::sort(q.begin(), q.end());
  return q;
}

// The radius of each point (sphere or image).
std::vector<double> radii_of(const Centres& centres, const Frame& frame) {
  std::vector<double> r(centres.points.size());
  for (std::size_t p = 0; p < r.size(); ++p) r[p] = frame.radius()[centres.particle[p]];
  return r;
}

// What a vertex of the lifted triangulation is checked against: the cells' pores (their
// four spheres), the spheres (a grid of them), and where a pore can be.
class Known {
 public:
  Known(const std::vector<DelaunayCell>& cells, const Centres& centres, const Frame& frame,
        const Region& primary, double length)
      : centres_(centres),
        radius_(radii_of(centres, frame)),
        primary_(primary),
        length_(length),
        grid_(centres.points, radius_, 2.0 * frame.radius().mean()) {
    container_.lo = frame.container.lo;
    container_.hi = frame.container.hi;
    for (const DelaunayCell& c : cells)
      if (c.pore && !c.flat) known_.push_back(sorted(c.vertices));
    std::sort(known_.begin(), known_.end());
  }

  const std::vector<double>& radii() const { return radius_; }

  // A vertex no cell gave, where a pore can be, and clear of every sphere (the
  // triangulation's bounds already are; this guards rounding).
  bool is_missing(const LiftedVertex& v) const {
    return counts(v.sphere.centre) &&
           !std::binary_search(known_.begin(), known_.end(), v.spheres) &&
           !overlaps_any(v.sphere, v.spheres,
                         grid_.overlapping(v.sphere.centre, v.sphere.radius, length_));
  }

 private:
  // Inside the container (beyond its walls lie vertices outside the packing's hull, which
  // no cell gives either: below a floor, behind a wall), and along periodic axes inside
  // the primary box, whose images give the rest.
  bool counts(const Eigen::Vector3d& x) const {
    for (int a = 0; a < 3; ++a) {
      const bool periodic = std::isfinite(primary_.lo[a]);
      const double lo = periodic ? primary_.lo[a] : container_.lo[a];
      const double hi = periodic ? primary_.hi[a] : container_.hi[a];
      if (x[a] < lo || x[a] > hi) return false;
    }
    return true;
  }

  bool overlaps_any(const TangentSphere& s, const Quadruple& q,
                    const std::vector<std::uint32_t>& spheres) const {
    for (std::uint32_t p : spheres) {
      if (std::find(q.begin(), q.end(), p) != q.end()) continue;
      if (overlap_by_more_than(centres_.points[p], radius_[p], s.centre, s.radius, length_))
        return true;
    }
    return false;
  }

  const Centres& centres_;
  std::vector<double> radius_;
  Region primary_, container_;  // container_: its box
  double length_;
  SphereGrid grid_;
  std::vector<Quadruple> known_;  // sorted
};

using Found = std::vector<LiftedVertex>;

Found lifted_missing(const Known& known, const Centres& centres, double length) {
  Found all;
  for (const LiftedVertex& v : lifted_vertices(centres.points, known.radii(), length))
    if (known.is_missing(v)) all.push_back(v);
  return all;
}

// One vertex of each sphere: a vertex of five or more spheres on one sphere is given by
// several quadruples, of which a cell may hold one; the first in the spheres' order stays.
Found one_of_each_sphere(Found all, const std::vector<DelaunayCell>& cells, double length) {
  struct Entry {
    Eigen::Vector3d centre;
    std::size_t vertex;  // in all; all.size() for a cell's pore, which always stays
  };
  std::vector<Entry> entries;
  for (const DelaunayCell& c : cells)
    if (c.pore && !c.flat) entries.push_back({c.centre, all.size()});
  for (std::size_t v = 0; v < all.size(); ++v) entries.push_back({all[v].sphere.centre, v});
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.centre[0], a.vertex) < std::tie(b.centre[0], b.vertex);
  });
  std::vector<bool> dropped(all.size(), false);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (entries[i].vertex == all.size()) continue;
    for (std::size_t j = i; j-- > 0 && entries[i].centre[0] - entries[j].centre[0] <= length;) {
      const bool kept = entries[j].vertex == all.size() || !dropped[entries[j].vertex];
      if (!kept || (entries[i].centre - entries[j].centre).norm() > length) continue;
      if (entries[j].vertex != all.size() && entries[i].vertex < entries[j].vertex) {
        dropped[entries[j].vertex] = true;  // the earlier quadruple stays
        continue;
      }
      dropped[entries[i].vertex] = true;
      break;
    }
  }
  Found one;
  for (std::size_t v = 0; v < all.size(); ++v)
    if (!dropped[v]) one.push_back(all[v]);
  return one;
}

}  // namespace

std::vector<Pore> missing_vertices(const std::vector<DelaunayCell>& cells, const Centres& centres,
                                   const Frame& frame, const Region& primary, double mean_radius,
                                   double length) {
  Found all = lifted_missing(Known(cells, centres, frame, primary, length), centres, length);
  // Each face (four spheres) comes once: in the spheres' order, whatever the triangulation's.
  std::sort(all.begin(), all.end(),
            [](const LiftedVertex& a, const LiftedVertex& b) { return a.spheres < b.spheres; });
  all = one_of_each_sphere(std::move(all), cells, length);
  std::vector<Pore> pores;
  pores.reserve(all.size());
  for (const LiftedVertex& v : all)
    pores.push_back({v.sphere.centre, v.sphere.radius + mean_radius, 0});
  return pores;
}

}  // namespace granpipe::pores
