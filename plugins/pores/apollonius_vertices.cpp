#include "apollonius_vertices.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "lifted_vertices.hpp"
#include "pore_region.hpp"
#include "sphere_grid.hpp"
#include "tangent_sphere.hpp"

namespace granpipe::pores {

namespace {

using Quadruple = std::array<std::uint32_t, 4>;  // sorted point rows

struct Vertex {
  Quadruple spheres;
  TangentSphere sphere;
};

Quadruple sorted(Quadruple q) {
  std::sort(q.begin(), q.end());
  return q;
}

class Search {
 public:
  Search(const std::vector<DelaunayCell>& cells, const Centres& centres, const Frame& frame,
         const Region& primary, double length)
      : centres_(centres),
        radius_(centres.points.size()),
        primary_(primary),
        length_(length),
        margin_(frame.radius().mean()) {
    bounds_.lo.setConstant(std::numeric_limits<double>::infinity());
    bounds_.hi = -bounds_.lo;
    for (std::size_t p = 0; p < radius_.size(); ++p) {
      radius_[p] = frame.radius()[centres.particle[p]];
      const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius_[p]);
      bounds_.lo = bounds_.lo.cwiseMin(centres.points[p] - r);
      bounds_.hi = bounds_.hi.cwiseMax(centres.points[p] + r);
    }
    grid_.emplace(centres.points, radius_, 2.0 * frame.radius().mean());
    for (const DelaunayCell& c : cells) {
      if (!c.pore || c.flat) continue;
      known_.push_back(sorted(c.vertices));
      if (counts(c.centre, 0.0)) widest_ = std::max(widest_, c.radius - frame.radius().mean());
    }
    std::sort(known_.begin(), known_.end());
  }

  std::optional<TangentSphere> solve(const Quadruple& q) const {
    std::array<Eigen::Vector3d, 4> x;
    std::array<double, 4> r{};
    for (int k = 0; k < 4; ++k) {
      x[k] = centres_.points[q[k]];
      r[k] = radius_[q[k]];
    }
    return tangent_sphere(x, r);
  }

  // Whether the search around t can find a vertex that counts. Wider tangent spheres than
  // twice the widest pore of a cell (slivers, the hull) overlap many spheres: a search
  // around them would be long, and each vertex the cells miss lies in a tangent sphere at
  // most 1.5 times as wide as its own in the packings tested (docs/notes/pores-apollonius.md).
  bool worth_searching(const TangentSphere& t) const {
    return t.radius <= 2.0 * widest_ && counts(t.centre, reach(t));
  }

  // A vertex of the lifted triangulation that no cell gave: not a cell's quadruple, and
  // clear of every sphere (the triangulation's bounds already are; this guards rounding).
  bool is_missing(const LiftedVertex& v) const {
    return !std::binary_search(known_.begin(), known_.end(), v.spheres) &&
           !overlaps_any(v.sphere, v.spheres,
                         grid_->overlapping(v.sphere.centre, v.sphere.radius, length_));
  }

  double largest_over_smallest_radius() const {
    const auto [small, large] = std::minmax_element(radius_.begin(), radius_.end());
    return *large / *small;
  }

  // The vertices whose four spheres come within reach of the cell's tangent sphere t.
  void around(const TangentSphere& t, std::vector<Vertex>& found) const {
    std::vector<std::uint32_t> near = grid_->overlapping(t.centre, reach(t), 0.0);
    std::sort(near.begin(), near.end());
    const std::size_t n = near.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        for (std::size_t k = j + 1; k < n; ++k)
          for (std::size_t l = k + 1; l < n; ++l) {
            const Quadruple q{near[i], near[j], near[k], near[l]};
            const std::optional<TangentSphere> s = solve(q);
            // The spheres near are the likeliest to overlap it: they are tried first.
            if (!s || overlaps_any(*s, q, near) ||
                overlaps_any(*s, q, grid_->overlapping(s->centre, s->radius, length_)) ||
                std::binary_search(known_.begin(), known_.end(), q))
              continue;
            found.push_back({q, *s});
          }
  }

 private:
  double reach(const TangentSphere& t) const { return t.radius + margin_; }

  // Inside the spheres' bounding box (beyond it lie the cells of their hull, whose tangent
  // spheres are wide), and along periodic axes (where the primary box is bounded) within
  // `reach` of the box.
  bool counts(const Eigen::Vector3d& x, double reach) const {
    if (!in_box(bounds_, x)) return false;
    Eigen::Vector3d outside = Eigen::Vector3d::Zero();
    for (int a = 0; a < 3; ++a)
      if (std::isfinite(primary_.lo[a]))
        outside[a] = std::max({primary_.lo[a] - x[a], x[a] - primary_.hi[a], 0.0});
    return outside.norm() <= reach;
  }

  bool overlaps_any(const TangentSphere& s, const Quadruple& q,
                    const std::vector<std::uint32_t>& spheres) const {
    for (std::uint32_t p : spheres) {
      if (std::find(q.begin(), q.end(), p) != q.end()) continue;
      const double touch = radius_[p] + s.radius - length_;
      if (touch > 0.0 && (centres_.points[p] - s.centre).squaredNorm() < touch * touch) return true;
    }
    return false;
  }

  const Centres& centres_;
  std::vector<double> radius_;
  Region primary_, bounds_;  // bounds_: of the spheres
  double length_, margin_;
  double widest_ = 0.0;  // the largest pore of a cell that counts
  std::optional<SphereGrid> grid_;
  std::vector<Quadruple> known_;  // sorted
};

using Found = std::vector<Vertex>;

Found searched_around(const Search& search, const std::vector<DelaunayCell>& cells,
                      const std::vector<std::size_t>& left_out, int threads) {
  std::vector<TangentSphere> seeds;
  for (std::size_t c : left_out) {
    const std::optional<TangentSphere> t = search.solve(sorted(cells[c].vertices));
    if (t && search.worth_searching(*t)) seeds.push_back(*t);
  }
  std::vector<Found> found(seeds.size());
  const auto n = static_cast<std::ptrdiff_t>(seeds.size());
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (std::ptrdiff_t s = 0; s < n; ++s) search.around(seeds[s], found[s]);
  Found all;
  for (const Found& f : found) all.insert(all.end(), f.begin(), f.end());
  return all;
}

Found lifted_missing(const Search& search, const Centres& centres, const Frame& frame,
                     double length) {
  std::vector<double> radii(centres.points.size());
  for (std::size_t p = 0; p < radii.size(); ++p) radii[p] = frame.radius()[centres.particle[p]];
  Found all;
  for (const LiftedVertex& v : lifted_vertices(centres.points, radii, length))
    if (search.is_missing(v)) all.push_back({v.spheres, v.sphere});
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

std::vector<Pore> missing_vertices(const std::vector<DelaunayCell>& cells,
                                   const std::vector<std::size_t>& left_out, const Centres& centres,
                                   const Frame& frame, const Region& primary, double mean_radius,
                                   double length, int threads) {
  if (left_out.empty()) return {};
  const Search search(cells, centres, frame, primary, length);
  Found all = search.largest_over_smallest_radius() > kSearchedRadiusRatio
                  ? lifted_missing(search, centres, frame, length)
                  : searched_around(search, cells, left_out, threads);
  const auto by_spheres = [](const Vertex& a, const Vertex& b) { return a.spheres < b.spheres; };
  std::stable_sort(all.begin(), all.end(), by_spheres);
  all.erase(std::unique(all.begin(), all.end(),
                        [](const Vertex& a, const Vertex& b) { return a.spheres == b.spheres; }),
            all.end());
  all = one_of_each_sphere(std::move(all), cells, length);
  std::vector<Pore> pores;
  pores.reserve(all.size());
  for (const Vertex& v : all) pores.push_back({v.sphere.centre, v.sphere.radius + mean_radius, 0});
  return pores;
}

}  // namespace granpipe::pores
