#include "disk_packing.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "granpipe/cell_list.hpp"
#include "granpipe/container_check.hpp"
#include "granpipe/errors.hpp"

namespace granpipe::disks2d_tap {

void DiskPacking::add(double xi, double yi, double ri) {
  x.push_back(xi);
  y.push_back(yi);
  r.push_back(ri);
  first.push_back(kNone);
  second.push_back(kNone);
}

void DiskPacking::clear_supports() {
  std::fill(first.begin(), first.end(), kNone);
  std::fill(second.begin(), second.end(), kNone);
}

double DiskPacking::min_radius() const {
  return r.empty() ? 0.0 : *std::min_element(r.begin(), r.end());
}

double DiskPacking::max_radius() const {
  return r.empty() ? 0.0 : *std::max_element(r.begin(), r.end());
}

double DiskPacking::top() const {
  double t = 0.0;
  for (std::size_t i = 0; i < size(); ++i) t = std::max(t, y[i] + r[i]);
  return t;
}

double DiskPacking::contact_x(std::size_t i, PartnerCode p) const {
  if (p == kLeftWall) return 0.0;
  if (p == kRightWall) return width;
  if (p == kBase) return x[i];
  const auto j = static_cast<std::size_t>(p);
  return x[i] + r[i] * (x[j] - x[i]) / (r[i] + r[j]);
}

double DiskPacking::contact_y(std::size_t i, PartnerCode p) const {
  if (is_side_wall(p)) return y[i];
  if (p == kBase) return 0.0;
  const auto j = static_cast<std::size_t>(p);
  return y[i] + r[i] * (y[j] - y[i]) / (r[i] + r[j]);
}

void DiskPacking::check(const std::string& where, double tolerance) const {
  auto fail = [&](std::size_t i, const std::string& what) {
    std::ostringstream s;
    s.precision(17);
    s << where << ": disk " << i << " at (" << x[i] << ", " << y[i] << ") radius " << r[i] << ": "
      << what;
    throw InputError(s.str());
  };
  if (!(width > 0.0) || !std::isfinite(width)) {
    throw InputError(where + ": expected a finite box width > 0, got " + std::to_string(width));
  }
  if (y.size() != x.size() || r.size() != x.size() || first.size() != x.size() ||
      second.size() != x.size()) {
    throw InputError(where + ": expected one y, radius and support pair per disk");
  }
  for (std::size_t i = 0; i < size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) fail(i, "expected a finite position");
    if (!(r[i] > 0.0) || !std::isfinite(r[i])) fail(i, "expected a finite radius > 0");
    const double slack = tolerance * r[i];
    if (x[i] - r[i] < -slack || x[i] + r[i] > width + slack || y[i] - r[i] < -slack) {
      fail(i, "expected the disk inside the box [0, " + std::to_string(width) + "] x [0, inf)");
    }
  }
  if (size() < 2) return;
  Coordinates pos(static_cast<Eigen::Index>(size()), 2);
  for (std::size_t i = 0; i < size(); ++i) {
    pos(static_cast<Eigen::Index>(i), 0) = x[i];
    pos(static_cast<Eigen::Index>(i), 1) = y[i];
  }
  const Container box =
      Container::open_top_box(2, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(width, top(), 0));
  const CellList cells(pos, box, 2, 2.0 * max_radius());
  cells.for_each_pair([&](int i, int j, const double*, double r2) {
    const double reach = r[i] + r[j] - tolerance * std::min(r[i], r[j]);
    if (r2 < reach * reach) {
      fail(static_cast<std::size_t>(i), "overlaps disk " + std::to_string(j) + " by " +
                                            std::to_string(r[i] + r[j] - std::sqrt(r2)) +
                                            ", expected no overlap");
    }
  });
}

Property supports_property() {
  return {"supports",
          Scope::Particle,
          ValueType::Integer,
          2,
          "",
          "left and right support of each disk (particle index, -1 none, -2 - wall)"};
}
Property tap_property() { return {"tap", Scope::Frame, ValueType::Integer, 1, "", "tap number"}; }
Property cycle_property() {
  return {"cycle",
          Scope::Frame,
          ValueType::Integer,
          1,
          "",
          "half-cycle of a ramped protocol (0 first increase, odd decreasing), -1 constant"};
}
Property amplitude_property() {
  return {"amplitude", Scope::Frame, ValueType::Real, 1, "1", "tap amplitude A"};
}

void DiskPacking::to_frame(Frame& frame) const {
  const auto n = static_cast<Eigen::Index>(size());
  frame.resize(n, 2);
  ValueTable<std::int64_t>& labels =
      frame.particles.add<ValueTable<std::int64_t>>(supports_property());
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    frame.position()(k, 0) = x[i];
    frame.position()(k, 1) = y[i];
    frame.radius()[k] = r[i];
    PartnerCode left = first[i], right = second[i];
    if (first[i] == kBase) {
      right = kBase;
    } else if (second[i] != kNone) {
      if (contact_x(i, second[i]) < contact_x(i, first[i])) std::swap(left, right);
    } else if (first[i] != kNone && contact_x(i, first[i]) > x[i]) {
      std::swap(left, right);  // a single support (only mid-deposition) on the right side
    }
    labels(k, 0) = left;
    labels(k, 1) = right;
  }
  frame.container =
      Container::open_top_box(2, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(width, top(), 0));
}

DiskPacking DiskPacking::from_frame(const Frame& frame, const std::string& where) {
  if (frame.dim != 2) {
    throw InputError(where + ": expected a 2D frame, got " + std::to_string(frame.dim) + "D");
  }
  // The engine's box has its left wall at x = 0 and its base at y = 0, at rest: a base
  // raised by 1.5 (lo or wall_offset) was read as one at 0, the disks on it left floating.
  const Container& c = frame.container;
  const std::string moving = walls_not_at_rest(c, 2);
  if (c.lo.x() != 0.0 || c.lo.y() != 0.0 || !moving.empty()) {
    std::ostringstream s;
    s.precision(17);
    s << where << ": expected a box whose left wall is at x = 0 and base at y = 0, at rest, got ";
    if (moving.empty()) {
      s << "x = " << c.lo.x() << " and y = " << c.lo.y();
    } else {
      s << moving;
    }
    throw InputError(s.str());
  }
  // The engine's box has side walls and a base: a periodic frame was read as walled.
  const auto& sides = frame.container.boundary;
  for (const auto& [side, name] :
       {std::pair{sides[0][0], "x_low"}, {sides[0][1], "x_high"}, {sides[1][0], "y_low"}}) {
    if (side != Boundary::Wall || frame.container.shape != ContainerShape::Box) {
      throw InputError(where +
                       ": expected a box with walls at x_low, x_high and y_low (the base), got " +
                       std::string(frame.container.shape != ContainerShape::Box
                                       ? to_string(frame.container.shape)
                                       : to_string(side)) +
                       " at " + name);
    }
  }
  DiskPacking p;
  p.width = frame.container.hi.x();
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    p.add(frame.position()(k, 0), frame.position()(k, 1), frame.radius()[k]);
  }
  p.check(where, 1e-9);
  return p;
}

}  // namespace granpipe::disks2d_tap
