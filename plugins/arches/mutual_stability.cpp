#include "mutual_stability.hpp"

#include <cmath>
#include <utility>

#include "granpipe/container_check.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/particles_outside.hpp"
#include "granpipe/separation.hpp"

namespace granpipe::arches {

namespace {

bool is_valid_partner(std::int64_t p, Eigen::Index self, Eigen::Index n) {
  if (partner::is_particle(p)) return p < n && p != self;
  return p == partner::none || p == partner::wall(Wall::XLow) || p == partner::wall(Wall::XHigh) ||
         p == partner::wall(Wall::YLow);
}

void check_side(const IndexArray& side, const char* name, const Container& c,
                const std::string& where) {
  const Eigen::Index n = side.size();
  const auto label = [&](Eigen::Index i) {
    return where + ": supports." + name + "[" + std::to_string(i) + "]: ";
  };
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::int64_t p = side(i);
    if (!is_valid_partner(p, i, n)) {
      throw InputError(label(i) + "expected a disk index in [0, " + std::to_string(n) +
                       ") other than " + std::to_string(i) + ", " + std::to_string(partner::none) +
                       " (none), " + std::to_string(partner::wall(Wall::XLow)) + " (left wall), " +
                       std::to_string(partner::wall(Wall::XHigh)) + " (right wall) or " +
                       std::to_string(partner::wall(Wall::YLow)) + " (base), got " +
                       std::to_string(p));
    }
    // Side walls labelled in a box periodic along x made an arch "supported" at both ends
    // by walls that are not there (exit 0).
    if (partner::is_wall(p) && !has_wall(c, 2, partner::wall_of(p))) {
      throw InputError(label(i) + "expected a support the container has, got " + std::to_string(p) +
                       " (wall " + to_string(partner::wall_of(p)) + "), a side it has none on");
    }
  }
}

bool has_left_partner(const Supports& s, Eigen::Index i) {
  const std::int64_t j = s.left(i);
  return partner::is_particle(j) && s.right(j) == i;
}

}  // namespace

void check_supports(const Frame& frame, const std::string& where) {
  if (frame.dim != 2) {
    throw InputError(where + ": dim: expected a 2D frame, got " + std::to_string(frame.dim) + "D");
  }
  if (!frame.has("supports")) {
    throw InputError(where +
                     ": supports: expected support labels (from a 2D pseudo-dynamics source), "
                     "got none");
  }
  const Supports s = Supports::of(frame);
  const Eigen::Index n = frame.size();
  if (s.left.size() != n || s.right.size() != n) {
    throw InputError(where + ": supports: expected " + std::to_string(n) +
                     " left and right labels, got " + std::to_string(s.left.size()) + " and " +
                     std::to_string(s.right.size()));
  }
  check_side(s.left, "left", frame.container, where);
  check_side(s.right, "right", frame.container, where);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (partner::is_particle(s.left(i)) && s.left(i) == s.right(i)) {
      throw InputError(where + ": supports[" + std::to_string(i) +
                       "]: expected two different supporting disks, got disk " +
                       std::to_string(s.left(i)) + " as both left and right support");
    }
  }
}

namespace {

// How far disk i's surface is from support p, and the most the rule allows.
std::pair<double, double> support_gap(const Frame& f, Eigen::Index i, std::int64_t p) {
  const double r = f.radius()[i];
  if (partner::is_wall(p)) return {surface_gap(f, i, partner::wall_of(p)), r};
  const double rp = f.radius()[p];
  return {separation(f, i, p).norm() - r - rp, std::min(r, rp)};
}

}  // namespace

void check_supports_touch(const Frame& frame, const std::string& where) {
  const Supports s = Supports::of(frame);
  for (const auto& [side, name] : {std::pair{&s.left, "left"}, {&s.right, "right"}}) {
    for (Eigen::Index i = 0; i < frame.size(); ++i) {
      const std::int64_t p = (*side)(i);
      if (p == partner::none) continue;
      const auto [gap, most] = support_gap(frame, i, p);
      if (!(gap > most)) continue;
      const bool wall = partner::is_wall(p);
      const std::string support = wall ? "wall " + std::string(to_string(partner::wall_of(p)))
                                       : "disk " + std::to_string(p);
      throw InputError(where + ": supports." + name + "[" + std::to_string(i) +
                       "]: expected a support touching disk " + std::to_string(i) + ", got " +
                       support + ", its surface " + format_number(gap) + " away (more than " +
                       (wall ? "its radius, " : "the smaller radius, ") + format_number(most) +
                       ")");
    }
  }
}

namespace {

// Whether support p of disk i is on the side `left` says.
bool on_its_side(const Frame& f, Eigen::Index i, std::int64_t p, bool left) {
  if (p == partner::none || p == partner::wall(Wall::YLow)) return true;
  if (partner::is_wall(p)) return partner::wall_of(p) == (left ? Wall::XLow : Wall::XHigh);
  const double to_support = separation(f, i, p).x();  // x of p minus x of i
  return left ? to_support <= 0.0 : to_support >= 0.0;
}

}  // namespace

void check_support_sides(const Frame& frame, const std::string& where) {
  const Supports s = Supports::of(frame);
  for (const auto& [side, left] : {std::pair{&s.left, true}, {&s.right, false}}) {
    for (Eigen::Index i = 0; i < frame.size(); ++i) {
      const std::int64_t p = (*side)(i);
      if (on_its_side(frame, i, p, left)) continue;
      const std::string name = left ? "left" : "right";
      const std::string support = partner::is_wall(p)
                                      ? "the wall " + std::string(to_string(partner::wall_of(p)))
                                      : "disk " + std::to_string(p) + ", " +
                                            format_number(std::abs(separation(frame, i, p).x())) +
                                            " to its " + (left ? "right" : "left");
      throw InputError(where + ": supports." + name + "[" + std::to_string(i) +
                       "]: expected a support on disk " + std::to_string(i) + "'s " + name +
                       " (the " + name + " wall, the base or a disk), got " + support);
    }
  }
}

Property supports_property() {
  return {"supports",
          Scope::Particle,
          ValueType::Integer,
          2,
          "",
          "left and right support of each disk (particle index, -1 none, -2 - wall)"};
}

Supports Supports::of(const Frame& frame) {
  const ValueTable<std::int64_t>& t = frame.table<std::int64_t>("supports");
  return {t.col(0), t.col(1)};
}

Property arch_property() {
  return {"arch",
          Scope::Particle,
          ValueType::Integer,
          1,
          "",
          "index of the arch holding the disk in this frame, -1 for none"};
}

IndexArray arch_of_each_disk(Eigen::Index disks, const std::vector<Arch>& arches) {
  IndexArray arch = IndexArray::Constant(disks, -1);
  for (std::size_t k = 0; k < arches.size(); ++k) {
    for (Eigen::Index d : arches[k].disks) arch[d] = static_cast<std::int64_t>(k);
  }
  return arch;
}

std::int64_t right_mutual_partner(const Supports& s, Eigen::Index i) {
  const std::int64_t j = s.right(i);
  return partner::is_particle(j) && s.left(j) == i ? j : partner::none;
}

std::vector<Arch> find_arches(const Frame& frame, const std::string& where) {
  const Supports s = Supports::of(frame);
  const Eigen::Index n = frame.size();
  std::vector<Arch> arches;
  std::vector<char> in_arch(static_cast<std::size_t>(n), 0);
  // Each disk has at most one mutual partner on each side, so the links form paths (and,
  // with labels no deposition can produce, rings). A path is walked from its left end,
  // the disk without a partner on its left, along right partners.
  for (Eigen::Index first = 0; first < n; ++first) {
    if (has_left_partner(s, first) || right_mutual_partner(s, first) == partner::none) continue;
    Arch arch;
    double dx = 0.0;
    Eigen::Index k = first;
    arch.disks.push_back(k);
    for (std::int64_t j = right_mutual_partner(s, k); j != partner::none;
         j = right_mutual_partner(s, k)) {
      dx += frame.container.minimum_image(0, frame.position()(j, 0) - frame.position()(k, 0));
      k = j;
      arch.disks.push_back(k);
    }
    arch.span = std::abs(dx);
    for (Eigen::Index d : arch.disks) in_arch[static_cast<std::size_t>(d)] = 1;
    arches.push_back(std::move(arch));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!in_arch[static_cast<std::size_t>(i)] && has_left_partner(s, i)) {
      throw InputError(where +
                       ": supports: expected chains of mutually stable disks, got a ring "
                       "of mutual supports through disk " +
                       std::to_string(i));
    }
  }
  return arches;
}

}  // namespace granpipe::arches
