#pragma once
// Spheres binned on a uniform grid, for the question a candidate pore asks: which spheres
// does a sphere of any size overlap? (The core's cell list answers within one fixed cutoff;
// a pore in a loose packing can be wider than any cutoff chosen beforehand.)
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace granpipe::pores {

// Whether the spheres (a, ra) and (b, rb) overlap by more than `length`.
inline bool overlap_by_more_than(const Eigen::Vector3d& a, double ra, const Eigen::Vector3d& b,
                                 double rb, double length) {
  const double touch = ra + rb - length;
  return touch > 0.0 && (a - b).squaredNorm() < touch * touch;
}

class SphereGrid {
 public:
  // Cells of side `cell`; the centres may lie anywhere (periodic images beyond the box).
  SphereGrid(const std::vector<Eigen::Vector3d>& centres, std::vector<double> radii, double cell);

  // The spheres that the sphere (centre, radius) overlaps by more than `length`.
  std::vector<std::uint32_t> overlapping(const Eigen::Vector3d& centre, double radius,
                                         double length) const;
  // Whether it overlaps by more than `length` one of the spheres `counted` (a predicate on
  // their index) accepts; stops at the first.
  template <class Counted>
  bool overlaps_any(const Eigen::Vector3d& centre, double radius, double length,
                    Counted&& counted) const {
    bool any = false;
    for_each_overlapping(centre, radius, length, [&](std::uint32_t i) {
      any = counted(i);
      return !any;
    });
    return any;
  }

 private:
  std::array<int, 3> cell_of(const Eigen::Vector3d& x) const;
  std::size_t index(const std::array<int, 3>& c) const;
  // Calls visit(i) for each sphere (centre, radius) overlaps by more than `length`, until
  // it returns false.
  template <class Visit>
  void for_each_overlapping(const Eigen::Vector3d& centre, double radius, double length,
                            Visit&& visit) const {
    const double reach = radius + largest_radius_;
    const std::array<int, 3> from = cell_of(centre - Eigen::Vector3d::Constant(reach));
    const std::array<int, 3> to = cell_of(centre + Eigen::Vector3d::Constant(reach));
    for (int z = from[2]; z <= to[2]; ++z)
      for (int y = from[1]; y <= to[1]; ++y)
        for (int x = from[0]; x <= to[0]; ++x) {
          const std::size_t k = index({x, y, z});
          for (std::uint32_t s = start_[k]; s < start_[k + 1]; ++s) {
            const std::uint32_t i = order_[s];
            if (overlap_by_more_than(centres_[i], radii_[i], centre, radius, length) && !visit(i))
              return;
          }
        }
  }

  const std::vector<Eigen::Vector3d>& centres_;
  std::vector<double> radii_;
  double cell_, largest_radius_ = 0.0;
  Eigen::Vector3d lo_;
  std::array<int, 3> n_{1, 1, 1};
  std::vector<std::uint32_t> start_, order_;  // the spheres of cell k: order_[start_[k]..]
};

}  // namespace granpipe::pores
