#include "saved_packing.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "granpipe/container.hpp"
#include "granpipe/container_check.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "sphere_grid.hpp"

namespace granpipe::spheres3d_tap {

namespace {

constexpr double kTolerance = 1e-9;  // of R: rounding of a saved packing, not an overlap

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// How the saved frame's container differs from the model's (the box of side L over a
// bottom wall at z = 0, its walls at rest), or "" where it does not. The model puts the
// spheres in its own box: a cylinder was read as the square around it, a base raised by a
// wall offset as one at z = 0, a side periodic along x alone as a wall. Its top is no
// matter: the model's is open, another tool's H5MD file has a wall there (H5MD's
// boundary "none").
std::string container_difference(const Container& c, const TapBox& box) {
  if (c.shape != ContainerShape::Box) return std::string("a ") + to_string(c.shape) + " container";
  if (c.lo.norm() != 0.0 || std::abs(c.hi.x() - box.side) > 1e-12 * box.side ||
      std::abs(c.hi.y() - box.side) > 1e-12 * box.side) {
    std::ostringstream s;
    s.precision(17);
    s << "[" << c.lo.x() << ", " << c.hi.x() << "] x [" << c.lo.y() << ", " << c.hi.y()
      << "] over a bottom at z = " << c.lo.z();
    return s.str();
  }
  const Container model = box.container(c.hi.z());
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const bool top = axis == 2 && side == 1;
      if (top || c.boundary[axis][side] == model.boundary[axis][side]) continue;
      return std::string(to_string(c.boundary[axis][side])) + " at " +
             to_string(static_cast<Wall>(2 * axis + side));
    }
  }
  return walls_not_at_rest(c, 3);
}

void check_box(const std::string& where, const Frame& f, const TapBox& box) {
  const std::string difference = container_difference(f.container, box);
  if (difference.empty()) return;
  throw InputError(where + ": expected a box [0, " + number(box.side) + "]^2 with " +
                   (box.periodic() ? "periodic" : "wall") +
                   " sides over a bottom wall at z = 0, at rest, got " + difference);
}

void check_inside(const std::string& where, const std::vector<Eigen::Vector3d>& x,
                  const TapBox& box) {
  const double r = box.radius, slack = kTolerance * r;
  for (std::size_t i = 0; i < x.size(); ++i) {
    bool out = x[i].z() < r - slack;
    if (!box.periodic())
      for (int a = 0; a < 2; ++a)
        out = out || x[i][a] < r - slack || x[i][a] > box.side - r + slack;
    if (out) {
      throw InputError(where + ": sphere " + std::to_string(i) + " at " + format_point(x[i], 17) +
                       " reaches through the bottom or a wall (radius " + number(r) + ")");
    }
  }
}

// Spheres that rest on one another stand at most a column of all n high. One far above
// (a frame of another run, or a typo) would not come down in the redeposition's short
// moves, so it rose with every dilation, and its height sized the grid of the search (a
// centre at 1e8 R took gigabytes).
void check_resting(const std::string& where, const std::vector<Eigen::Vector3d>& x,
                   const TapBox& box) {
  // A packing lifted off the bottom (every sphere 50 R up) was taken for a saved one, its
  // tap 0 measured as a packing of no density near the bottom (exit 0). A redeposited
  // packing's lowest sphere lies within a small step of the bottom; a whole diameter of
  // nothing under every sphere is no packing at rest.
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i].z() < x[lowest].z()) lowest = i;
  if (!x.empty() && x[lowest].z() > 3.0 * box.radius) {
    throw InputError(where + ": sphere " + std::to_string(lowest) + " at z = " +
                     number(x[lowest].z()) + ", the lowest: expected a packing at rest on the " +
                     "bottom, its lowest centre within a diameter of R = " + number(box.radius) +
                     " (the bottom's contact), got a gap of " +
                     number((x[lowest].z() - box.radius) / box.radius) + " R under every sphere");
  }
  const double highest = (2.0 * static_cast<double>(x.size()) - 1.0) * box.radius;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].z() > highest * (1.0 + kTolerance)) {
      throw InputError(where + ": sphere " + std::to_string(i) + " at z = " + number(x[i].z()) +
                       ": expected a packing at rest on the bottom, no centre higher than a "
                       "column of all " +
                       std::to_string(x.size()) + " spheres, (2N - 1) R = " + number(highest));
    }
  }
}

void check_overlaps(const std::string& where, const std::vector<Eigen::Vector3d>& x,
                    const TapBox& box) {
  SphereGrid grid(box);
  const double contact = 2.0 * box.radius * (1.0 - kTolerance);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Eigen::Vector3d lo = x[i].array() - contact, hi = x[i].array() + contact;
    grid.for_each_in(lo, hi, [&](std::int32_t j, const Eigen::Vector3d& shift) {
      const double d = (x[static_cast<std::size_t>(j)] + shift - x[i]).norm();
      if (d < contact) {
        throw InputError(where + ": spheres " + std::to_string(j) + " and " + std::to_string(i) +
                         " overlap (centres " + number(d) +
                         " apart, expected at least 2R = " + number(2.0 * box.radius) + ")");
      }
    });
    grid.put(static_cast<std::int32_t>(i), box.wrap(x[i]));
  }
}

}  // namespace

SavedPacking read_saved_packing(const StartFrame& start, const TapBox& box, long n) {
  const Frame& f = start.frame;
  const std::string& at = start.where;
  if (f.dim != 3)
    throw InputError(at + ": expected a 3D frame, got " + std::to_string(f.dim) + "D");
  f.check(at);  // a NaN centre named as such, not as a sphere through the bottom
  if (f.size() != n) {
    throw InputError(at + ": expected N = " + std::to_string(n) + " spheres, got " +
                     std::to_string(f.size()));
  }
  if (n > 0 && (f.radius() - box.radius).abs().maxCoeff() > 1e-12 * box.radius) {
    throw InputError(at + ": expected every radius equal to radius = " + number(box.radius) +
                     ", got " + number(f.radius().minCoeff()) + " to " +
                     number(f.radius().maxCoeff()));
  }
  check_box(at, f, box);
  // Along periodic sides any image is the sphere (another tool's file may hold any): the
  // checks searched around the image as given and filed it wrapped, passing an overlap
  // through the sides (exit 0) or finding two spheres in one cell (exit 1).
  std::vector<Eigen::Vector3d> x(static_cast<std::size_t>(n));
  for (long k = 0; k < n; ++k)
    x[static_cast<std::size_t>(k)] = box.wrap(f.position().row(k).transpose());
  check_inside(at, x, box);
  check_resting(at, x, box);
  check_overlaps(at, x, box);
  return {x,
          f.step,
          f.integer_observable("tap"),
          at,
          f.real_observable("epsilon"),
          f.integer_observable("leg")};
}

}  // namespace granpipe::spheres3d_tap
