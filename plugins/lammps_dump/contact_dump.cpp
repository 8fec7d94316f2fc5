#include "contact_dump.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/separation.hpp"
#include "granpipe/text_words.hpp"
#include "position_precision.hpp"
#include "snapshot_header.hpp"
#include "wall_partner.hpp"

namespace granpipe::lammps_dump {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The words of one entry line and where they are, for its values and messages.
struct Entry {
  const SnapshotPlace& place;
  long line;
  const std::vector<std::string_view>& words;

  std::string at() const { return place.at(line); }
  double value(int column) const {
    const std::string_view w = words[static_cast<std::size_t>(column)];
    const auto x = real_number(w);
    if (!x || !std::isfinite(*x)) {
      throw InputError(at() + "expected a finite number in column " + std::to_string(column + 1) +
                       ", got \"" + std::string(w) + "\"");
    }
    return *x;
  }
  Eigen::Vector3d vector(const std::array<int, 3>& at) const {
    return {value(at[0]), value(at[1]), value(at[2])};
  }
};

// The frame row of the atom an entry names (ids written as %g numbers: "51", "1e+06"). An id
// printed to fewer digits than it has ("1.23457e+06" for 1234567) names no atom for sure.
std::int64_t row_of(const Entry& e, int column, const Frame& f, const std::string& frame_place) {
  const std::string_view word = e.words[static_cast<std::size_t>(column)];
  if (printed_rounding(word) > 0.5) {
    throw InputError(e.at() + "expected an atom id written to its last digit in column " +
                     std::to_string(column + 1) + ", got \"" + std::string(word) +
                     "\" (write the ids with %d: dump_modify format)");
  }
  const double id = e.value(column);
  const auto& ids = f.id();
  const auto* end = ids.data() + ids.size();
  const auto* found = std::lower_bound(ids.data(), end, static_cast<std::int64_t>(id));
  if (id != std::floor(id) || found == end || static_cast<double>(*found) != id) {
    throw InputError(e.at() + "expected the id of an atom of " + frame_place + " in column " +
                     std::to_string(column + 1) + ", got " + format_number(id) +
                     ", which it does not hold");
  }
  return found - ids.data();
}

Eigen::Vector3d centre(const Frame& f, std::int64_t row) {
  return f.position().row(row).transpose().matrix();
}

Eigen::Vector3d wrapped(const Container& c, Eigen::Vector3d x) {
  for (int a = 0; a < 3; ++a) x[a] = c.wrap(a, x[a]);
  return x;
}

// The tangential force on atom 1: its own columns, the whole force less the normal one,
// or NaN.
Eigen::Vector3d tangential_of(const Entry& e, const ContactColumns& c, const Eigen::Vector3d& n) {
  if (c.tangential[0] >= 0) return e.vector(c.tangential);
  if (c.force[0] >= 0) return e.vector(c.force) - n;
  return Eigen::Vector3d::Constant(kNaN);
}

// A contact is a pair that touches. Without `cutoff radius` LAMMPS' pair/local lists every
// pair within the pair style's cutoff, touching or not, and a dump of another run lists
// pairs anywhere: either would count pairs apart as contacts.
void check_touching(const Entry& e, const Frame& f, std::int64_t i, std::int64_t j, double distance,
                    double rounding) {
  const double reach = f.radius()[i] + f.radius()[j];
  if (distance <= reach + rounding + 1e-9 * reach) return;
  throw InputError(e.at() + "expected atoms " + std::to_string(f.id()[i]) + " and " +
                   std::to_string(f.id()[j]) + " that touch, got a gap of " +
                   format_number(distance - reach) + " between them (centres " +
                   format_number(distance) + " apart, radii summing to " + format_number(reach) +
                   ", positions known to " + format_number(rounding) +
                   "): give only contacts (LAMMPS: compute pair/local ... cutoff radius)");
}

// The overlap a pair's own column states (LIGGGHTS' delta, LAMMPS' dist) must be the one
// its atoms' positions give: a column of another snapshot or of another quantity would
// store a contact the configuration does not hold. They agree to the rounding of the
// positions and of the word written; the more precise of the two is kept.
double pair_overlap(const Entry& e, const ContactColumns& c, const Frame& f, std::int64_t i,
                    std::int64_t j, double distance, double rounding) {
  const double reach = f.radius()[i] + f.radius()[j];
  const int column = c.overlap >= 0 ? c.overlap : c.distance;
  if (column < 0) return reach - distance;
  const bool is_overlap = c.overlap >= 0;
  const double stated = e.value(column), expected = is_overlap ? reach - distance : distance;
  const double printed = printed_rounding(e.words[static_cast<std::size_t>(column)]);
  const double allowed = rounding + printed + 1e-9 * reach;
  if (std::abs(stated - expected) > allowed) {
    throw InputError(e.at() + "expected " + (is_overlap ? "an overlap" : "a distance") + " of " +
                     format_number(expected) + " in column " + std::to_string(column + 1) +
                     " (atoms " + std::to_string(f.id()[i]) + " and " + std::to_string(f.id()[j]) +
                     " as the snapshot places them, to within " + format_number(allowed) +
                     "), got " + format_number(stated));
  }
  if (printed >= rounding) return reach - distance;
  return is_overlap ? stated : reach - stated;
}

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// The angle whose cosine is given, in degrees (for messages).
double degrees_of_cosine(double cosine) {
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * kDegreesPerRadian;
}

// The normal force lies on the line of the centres: columns of another quantity (the
// tangential or the total force named as the normal one) were read as it, exit 0, and
// gave a mean force of a fifth. 8 degrees are allowed, and what the printed positions leave
// of the line's direction (`rounding` over the distance): a total force whose tangential
// part is under a seventh of it passes.
void check_along_centres(const Entry& e, const ContactColumns& c, const Frame& f,
                         const ContactRow& r, const Eigen::Vector3d& d, double rounding) {
  const double force = r.normal.norm(), distance = d.norm();
  const double allowed = std::min(std::acos(0.99) + rounding / distance, std::numbers::pi / 2);
  if (!(force > 0.0) || allowed >= std::numbers::pi / 2 ||
      std::abs(r.normal.dot(d)) >= std::cos(allowed) * force * distance)
    return;
  const double degrees = degrees_of_cosine(std::abs(r.normal.dot(d)) / (force * distance));
  throw InputError(e.at() + "expected the normal force (columns " +
                   std::to_string(c.normal[0] + 1) + " to " + std::to_string(c.normal[2] + 1) +
                   ") along the line of atoms " + std::to_string(f.id()[r.i]) + " and " +
                   std::to_string(f.id()[r.j]) + "'s centres, got it " + format_number(degrees) +
                   " degrees off it (" + format_number(allowed * kDegreesPerRadian) +
                   " allowed): are the columns named as the file has them?");
}

ContactRow pair_row(const Entry& e, const ContactColumns& c, const Frame& f,
                    const std::string& frame_place, double rounding) {
  ContactRow r;
  r.i = row_of(e, c.id1, f, frame_place);
  r.j = row_of(e, c.id2, f, frame_place);
  if (r.i == r.j) {
    throw InputError(e.at() + "expected two different atoms, got id " +
                     std::to_string(f.id()[r.i]) + " twice");
  }
  const Eigen::Vector3d d = separation(f, r.i, r.j);
  const double ri = f.radius()[r.i], distance = d.norm();
  check_touching(e, f, r.i, r.j, distance, rounding);
  r.overlap = pair_overlap(e, c, f, r.i, r.j, distance, rounding);
  r.normal = e.vector(c.normal);
  check_along_centres(e, c, f, r, d, rounding);
  r.tangential = tangential_of(e, c, r.normal);
  // The middle of the overlap, on the line of the centres, as the dem source places it.
  r.point = wrapped(f.container, centre(f, r.i) + (ri - 0.5 * r.overlap) / distance * d);
  return r;
}

// How far a wall contact's atom is from the wall, and to what rounding: from the entry's own
// point of contact where the file gives one (LIGGGHTS' pos, on the surface of a wall that
// may move or be a mesh the stated container only approximates), else from the stated wall
// nearest to the atom.
struct WallGap {
  double gap;
  double rounding;
  bool from_point;
};

// `wall`: the stated wall the point faces, or without one the wall nearest the atom;
// `to_point`: from the atom's centre to the entry's point, where it gives one.
WallGap wall_gap(const Entry& e, const ContactColumns& c, const WallTouch& wall,
                 const std::optional<Eigen::Vector3d>& to_point) {
  if (!to_point) return {wall.distance, 0.0, false};
  double rounding = 0.0;
  for (int a = 0; a < 3; ++a)
    rounding += printed_rounding(e.words[static_cast<std::size_t>(c.point[a])]);
  return {to_point->norm(), rounding, true};
}

// A wall contact's atom must touch its wall, and the overlap its column states (LIGGGHTS'
// delta) must be the one the gap gives: a wall file of another snapshot or run would store
// contacts the configuration does not hold. A point may be on the wall's surface or in the
// middle of the overlap: half the overlap of leeway.
double wall_overlap(const Entry& e, const ContactColumns& c, const Frame& f, std::int64_t i,
                    const WallGap& g, double rounding) {
  const double radius = f.radius()[i], expected = radius - g.gap;
  const std::string between = "(atom " + std::to_string(f.id()[i]) + "'s centre " +
                              format_number(g.gap) + " from the wall" +
                              (g.from_point ? " at the entry's point" : " nearest it") +
                              ", radius " + format_number(radius);
  double allowed = rounding + g.rounding + 1e-9 * radius;
  if (expected < -allowed) {
    throw InputError(e.at() + "expected an atom that touches a wall, got a gap of " +
                     format_number(-expected) + " " + between + ", positions known to " +
                     format_number(allowed) + ")");
  }
  if (c.overlap < 0) return expected;
  const double stated = e.value(c.overlap);
  allowed += printed_rounding(e.words[static_cast<std::size_t>(c.overlap)]) +
             (g.from_point ? 0.5 * std::abs(stated) : 0.0);
  if (std::abs(stated - expected) > allowed) {
    throw InputError(e.at() + "expected an overlap of " + format_number(expected) + " in column " +
                     std::to_string(c.overlap + 1) + " " + between + ", to within " +
                     format_number(allowed) + "), got " + format_number(stated));
  }
  return stated;
}

// A point on another wall than those stated went to the nearest stated one (a side wall's
// contact in a bed stated with its base only counted as a base contact, exit 0). The point
// lies off the atom's centre towards its wall: along the wall's normal, whatever the wall's
// motion (a shaken base is stated where it is lowest), to within a coarse mesh's facets.
// (Without a point, the wall nearest the atom is taken, facing it by construction.)
void check_point_faces_wall(const Entry& e, const Frame& f, std::int64_t i,
                            const WallTouch& touch) {
  constexpr double kLeastCosine = 0.9;  // 26 degrees
  if (touch.facing >= kLeastCosine) return;
  const double degrees = degrees_of_cosine(touch.facing);
  throw InputError(e.at() + "expected the point of atom " + std::to_string(f.id()[i]) +
                   "'s wall contact within 25.8 degrees of a stated wall's normal, got it " +
                   format_number(degrees) + " degrees off the closest, " +
                   std::string(to_string(touch.wall)) +
                   "'s: a wall the container does not state? (state its base, cylinder_radius or "
                   "side_walls)");
}

ContactRow wall_row(const Entry& e, const ContactColumns& c, const Frame& f,
                    const std::string& frame_place, double rounding) {
  ContactRow r;
  r.i = row_of(e, c.id1, f, frame_place);
  const Eigen::Vector3d x = centre(f, r.i);
  const double radius = f.radius()[r.i];
  // Across periodic sides by the nearest image.
  const std::optional<Eigen::Vector3d> to_point =
      c.point[0] >= 0 ? std::optional(separation_to(f, r.i, e.vector(c.point))) : std::nullopt;
  const auto touch =
      to_point ? facing_wall(f.container, x, *to_point) : nearest_wall(f.container, x);
  if (!touch) {
    throw InputError(e.at() +
                     "expected a wall of the stated container for the wall contact of "
                     "atom " +
                     std::to_string(f.id()[r.i]) +
                     ", got a container without walls "
                     "(state its base, cylinder_radius or side_walls)");
  }
  check_point_faces_wall(e, f, r.i, *touch);
  r.j = partner::wall(touch->wall);
  r.overlap = wall_overlap(e, c, f, r.i, wall_gap(e, c, *touch, to_point), rounding);
  r.normal = e.vector(c.normal);
  r.tangential = tangential_of(e, c, r.normal);
  r.point = to_point ? e.vector(c.point)
                     : Eigen::Vector3d(x + (radius - 0.5 * r.overlap) * touch->normal);
  return r;
}

// The line of each pair of atoms of one snapshot: a pair listed twice (as LAMMPS lists a
// pair straddling two processors with newton_pair off) would count its contact twice in
// the coordination, the force networks and the force PDF.
class PairLines {
 public:
  void add(const Entry& e, const Frame& f, const ContactRow& r) {
    const auto key = std::minmax(f.id()[r.i], f.id()[r.j]);
    const auto [first, added] = lines_.emplace(key, e.line);
    if (added) return;
    throw InputError(e.at() + "expected each pair of atoms once, got ids " +
                     std::to_string(key.first) + " and " + std::to_string(key.second) +
                     " again (first on line " + std::to_string(first->second) + ")");
  }

 private:
  std::map<std::pair<std::int64_t, std::int64_t>, long> lines_;
};

// A wall line repeated word for word is one contact written twice (an atom touching a mesh
// wall at two facets has two points of contact, and two lines that differ).
class WallLines {
 public:
  void add(const Entry& e) {
    std::string key;
    for (const std::string_view w : e.words) key.append(w).push_back(' ');
    const auto [first, added] = lines_.emplace(std::move(key), e.line);
    if (added) return;
    throw InputError(e.at() +
                     "expected each wall contact once, got the same entry again (first "
                     "on line " +
                     std::to_string(first->second) + ")");
  }

 private:
  std::map<std::string, long> lines_;
};

}  // namespace

ContactDump::ContactDump(std::string path, ContactColumns columns, bool wall,
                         const std::string& param)
    : lines_(std::move(path)),
      index_(complete_snapshots(lines_, kLocalDump)),
      columns_(columns),
      wall_(wall),
      param_(param) {
  if (index_.columns.size() != columns_.count) {
    throw InputError(index_.columns_at + "expected " + std::to_string(columns_.count) +
                     " columns, as " + param_ + "'s keywords give, got " +
                     std::to_string(index_.columns.size()));
  }
  for (std::size_t k = 0; k < index_.snapshots.size(); ++k)
    by_timestep_.emplace(index_.snapshots[k].timestep, k);
}

void ContactDump::check_timesteps(const DumpIndex& atoms, const std::string& atom_file) const {
  const std::int64_t last = atoms.snapshots.back().timestep;
  for (const SnapshotStart& s : index_.snapshots) {
    const bool matched =
        std::any_of(atoms.snapshots.begin(), atoms.snapshots.end(),
                    [&](const SnapshotStart& a) { return a.timestep == s.timestep; });
    if (matched || (atoms.cut && s.timestep > last)) continue;
    throw InputError(path() + ": timestep " + std::to_string(s.timestep) + ", line " +
                     std::to_string(s.line_before + 1) + ": expected a snapshot of " + atom_file +
                     "'s timesteps, got one " + atom_file + " does not have");
  }
}

void ContactDump::read(const Frame& frame, const std::string& frame_place, double rounding,
                       std::vector<ContactRow>& rows) {
  const auto found = by_timestep_.find(frame.step);
  if (found == by_timestep_.end()) {
    throw InputError(path() + ": expected a snapshot of timestep " + std::to_string(frame.step) +
                     " (" + frame_place + "), got none");
  }
  const SnapshotStart& start = index_.snapshots[found->second];
  lines_.seek(start.offset, start.line_before);
  std::string line;
  std::vector<std::string_view> words;
  try {
    next_line_of(SnapshotPlace{path(), start.line_before + 1}, lines_, line);
    const SnapshotHeader h = read_header(path(), lines_, line, kLocalDump);
    PairLines pairs;
    WallLines walls;
    for (std::int64_t k = 0; k < h.atoms; ++k) {
      next_line_of(h.place, lines_, line);
      split_words(line, words);
      const Entry e{h.place, lines_.number(), words};
      if (words.size() != columns_.count) {
        throw InputError(e.at() + "expected " + std::to_string(columns_.count) + " values, as " +
                         param_ + "'s keywords give, got " + std::to_string(words.size()) + ": " +
                         quoted(trimmed(line)));
      }
      rows.push_back(wall_ ? wall_row(e, columns_, frame, frame_place, rounding)
                           : pair_row(e, columns_, frame, frame_place, rounding));
      if (wall_) {
        walls.add(e);
      } else {
        pairs.add(e, frame, rows.back());
      }
    }
  } catch (const SnapshotCut& cut) {
    throw InputError(path() + ": expected " + cut.place.name() +
                     " to be complete, as it was when the source started, got a shorter file");
  }
}

}  // namespace granpipe::lammps_dump
