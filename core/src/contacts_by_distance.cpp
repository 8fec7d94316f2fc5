#include "granpipe/contacts_by_distance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "granpipe/cell_list.hpp"
#include "granpipe/coordinate_spacing.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {
namespace {

struct Found {
  std::int64_t i, j;
  double gap;
};

// Particle-wall contacts of the container's solid walls (moved by wall_offset).
void find_wall_contacts(const Frame& f, double tolerance, std::vector<Found>& out) {
  const Container& c = f.container;
  const Eigen::Index n = f.size();
  const bool cylinder = c.shape == ContainerShape::Cylinder;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double reach = f.radius()[k] * (1.0 + tolerance);
    for (int a = 0; a < f.dim; ++a) {
      if (cylinder && a < 2) continue;  // the side of a cylinder is one round wall
      for (int side = 0; side < 2; ++side) {
        if (c.boundary[a][side] != Boundary::Wall) continue;
        const double wall = c.wall_at(a, side);
        const double dist = side == 0 ? f.position()(k, a) - wall : wall - f.position()(k, a);
        if (dist <= reach)
          out.push_back({k, partner::wall(static_cast<Wall>(2 * a + side)), dist - f.radius()[k]});
      }
    }
    if (cylinder) {
      const double dx = f.position()(k, 0) - c.cylinder_center[0] - c.wall_offset[0];
      const double dy = f.position()(k, 1) - c.cylinder_center[1] - c.wall_offset[1];
      const double dist = c.cylinder_radius - std::hypot(dx, dy);
      if (dist <= reach)
        out.push_back({k, partner::wall(Wall::CylinderSide), dist - f.radius()[k]});
    }
  }
}

}  // namespace

void declare_contact_tolerance(Schema& schema) {
  schema
      .real(kContactToleranceName, kDefaultContactTolerance,
            "relative contact tolerance: two particles touch when their centre distance is "
            "at most (R_i + R_j)(1 + tol), a particle and a wall when the centre-wall "
            "distance is at most R_i (1 + tol)")
      // Beyond 1 a particle a whole diameter away would touch: no contact network has that
      // (1e300 was refused by the neighbour search, in its own terms).
      .range(0.0, 1.0);
}

IntArray DistanceContacts::coordination(Eigen::Index n, bool with_walls) const {
  IntArray z = IntArray::Zero(n);
  for (Eigen::Index k = 0; k < size(); ++k) {
    if (partner::is_particle(j[k])) {
      ++z[i[k]];
      ++z[j[k]];
    } else if (with_walls) {
      ++z[i[k]];
    }
  }
  return z;
}

DistanceContacts find_contacts_by_distance(const Frame& frame, double tolerance) {
  return find_contacts_by_distance(frame, tolerance, "frame at step " + std::to_string(frame.step));
}

DistanceContacts find_contacts_by_distance(const Frame& frame, double tolerance,
                                           const std::string& where) {
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) {
    throw InputError("contacts by distance: expected a finite tolerance >= 0, got " +
                     std::to_string(tolerance));
  }
  const Eigen::Index n = frame.size();
  std::vector<Found> pairs, walls;
  // A lone particle too: in a periodic box it may touch its own images, which the pair
  // loop does not count, and the search refuses such a box (a z of 0 came out, exit 0).
  if (n >= 1) {
    const double cutoff = 2.0 * frame.radius().maxCoeff() * (1.0 + tolerance);
    const CellList cells(frame.position(), frame.container, frame.dim, cutoff, where);
    cells.for_each_pair([&](int i, int j, const double*, double r2) {
      const double contact = (frame.radius()[i] + frame.radius()[j]) * (1.0 + tolerance);
      if (r2 <= contact * contact) {
        pairs.push_back({i, j, std::sqrt(r2) - frame.radius()[i] - frame.radius()[j]});
      }
    });
    std::sort(pairs.begin(), pairs.end(),
              [](const Found& a, const Found& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  }
  find_wall_contacts(frame, tolerance, walls);

  DistanceContacts out;
  out.tolerance = tolerance;
  out.pairs = static_cast<Eigen::Index>(pairs.size());
  const auto m = static_cast<Eigen::Index>(pairs.size() + walls.size());
  out.i.resize(m);
  out.j.resize(m);
  out.gap.resize(m);
  Eigen::Index k = 0;
  for (const auto* list : {&pairs, &walls}) {
    for (const Found& c : *list) {
      out.i[k] = c.i;
      out.j[k] = c.j;
      out.gap[k] = c.gap;
      ++k;
    }
  }
  return out;
}

std::string coarse_for_contacts(const Frame& frame, double tolerance) {
  // A tolerance of 0 asks for exact contacts, which no rounding gives: the user's choice.
  if (frame.size() == 0 || tolerance == 0.0) return "";
  const double farthest = largest_coordinate(frame);
  const double rounding = double_spacing(farthest);
  const double contact = 2.0 * frame.radius().minCoeff();
  // Two centres each off by up to a spacing per coordinate.
  if (!(2.0 * rounding > tolerance * contact)) return "";
  const double needed = 4.0 * rounding / contact;  // the schema's largest tolerance is 1
  return "positions up to " + format_number(farthest) + " from the origin are rounded to " +
         format_number(rounding) + ", more than half of contact_tolerance x the smallest " +
         "contact distance (" + format_number(tolerance * contact) +
         "): touching particles may be missed; " +
         (needed <= 1.0 ? "raise contact_tolerance to " + format_number(needed) + " or " : "") +
         "move the origin into the packing";
}

std::string contacts_by_distance_key(double tolerance) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "contacts_by_distance(tolerance=%.17g)", tolerance);
  return buf;
}

const DistanceContacts& contacts_by_distance(const Frame& frame, FrameCache& cache,
                                             double tolerance) {
  return cache.get<DistanceContacts>(contacts_by_distance_key(tolerance),
                                     [&] { return find_contacts_by_distance(frame, tolerance); });
}

}  // namespace granpipe
