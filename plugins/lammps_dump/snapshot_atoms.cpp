#include "snapshot_atoms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/text_words.hpp"

namespace granpipe::lammps_dump {

namespace {

// The values of the atom lines in the file's order, before they are sorted by id.
struct AtomLines {
  std::vector<std::int64_t> ids;
  std::vector<std::int32_t> types;
  std::vector<long> lines;
  std::vector<double> values;           // per line: one for each column of `read`, in its order
  std::vector<int> read;                // the dump columns read as numbers
  std::vector<bool> finite;             // whether each of them must be finite
  int size = -1;                        // the radius or diameter column, which must be > 0
  std::vector<std::string_view> words;  // of the line being read
  PositionPrecision precision;
};

// Positions, size and vectors must be finite; kept columns are stored as they are (a NaN a
// compute wrote stays undefined).
void choose_columns(const AtomColumns& c, AtomLines& a) {
  auto add = [&](int column, bool finite) {
    a.read.push_back(column);
    a.finite.push_back(finite);
  };
  for (int k : c.position) add(k, true);
  if (c.size >= 0) add(c.size, true);
  a.size = c.size;
  for (const VectorColumn& v : c.vectors)
    for (int k : v.at) add(k, true);
  for (const KeptColumn& k : c.kept) add(k.at, false);
}

std::string column_name(const AtomColumns& c, int k) {
  return "column " + std::to_string(k + 1) + " (" + c.names[static_cast<std::size_t>(k)] + ")";
}

std::string all_names(const AtomColumns& c) {
  std::string s;
  for (const auto& n : c.names) s += (s.empty() ? "" : " ") + n;
  return s;
}

void parse_line(const std::string& line, const SnapshotPlace& place, long number,
                const AtomColumns& c, AtomLines& a) {
  split_words(line, a.words);
  const auto& w = a.words;
  auto at = [&] { return place.at(number); };  // built only for a message
  if (w.size() != c.count) {
    throw InputError(at() + "expected " + std::to_string(c.count) + " values (" + all_names(c) +
                     "), got " + std::to_string(w.size()) + ": " + quoted(line));
  }
  auto word = [&](int k) { return w[static_cast<std::size_t>(k)]; };
  // LAMMPS numbers atoms from 1.
  const auto id = whole_number(word(c.id));
  if (!id || *id < 1) {
    throw InputError(at() + "expected a whole number >= 1 in " + column_name(c, c.id) + ", got \"" +
                     std::string(word(c.id)) + "\"");
  }
  std::optional<std::int64_t> type = 1;
  if (c.type >= 0) type = whole_number(word(c.type));
  if (!type || *type < 1 || *type > std::numeric_limits<std::int32_t>::max()) {
    throw InputError(at() + "expected a type >= 1 in " + column_name(c, c.type) + ", got \"" +
                     std::string(word(c.type)) + "\"");
  }
  for (std::size_t k = 0; k < a.read.size(); ++k) {
    const auto value = real_number(word(a.read[k]));
    const bool size = a.read[k] == a.size;
    if (!value || (a.finite[k] && !std::isfinite(*value)) || (size && !(*value > 0))) {
      const char* kind = size ? "positive finite " : a.finite[k] ? "finite " : "";
      throw InputError(at() + "expected a " + kind + "number in " + column_name(c, a.read[k]) +
                       ", got \"" + std::string(word(a.read[k])) + "\"");
    }
    a.values.push_back(*value);
  }
  for (int axis = 0; axis < 3; ++axis) a.precision.add(axis, word(c.position[axis]));
  a.ids.push_back(*id);
  a.types.push_back(static_cast<std::int32_t>(*type));
  a.lines.push_back(number);
}

// The rows in id order; InputError for an id given twice.
std::vector<std::size_t> id_order(const AtomLines& a, const SnapshotPlace& place) {
  std::vector<std::size_t> order(a.ids.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return a.ids[i] < a.ids[j]; });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t first = order[k - 1], again = order[k];
    if (a.ids[first] != a.ids[again]) continue;
    throw InputError(place.at(a.lines[again]) + "expected each atom id once, got id " +
                     std::to_string(a.ids[again]) + " again (first on line " +
                     std::to_string(a.lines[first]) + ")");
  }
  return order;
}

// A coordinate more periods than this from a periodic box keeps under half its digits once
// wrapped into it: x = 1e300 in a box of side 4 wrapped to an arbitrary place, and was
// refused as an overlap of two other atoms.
constexpr double kMostPeriodsAway = 67108864.0;  // 2^26

// A position column's value in the box's coordinates, wrapped into periodic sides.
double position(double value, Coordinate kind, const Container& box, int axis,
                const SnapshotPlace& place, long line) {
  const bool scaled = kind == Coordinate::Scaled || kind == Coordinate::ScaledUnwrapped;
  const double x = scaled ? box.lo[axis] + value * box.length(axis) : value;
  if (box.periodic(axis) && !(std::abs(x - box.lo[axis]) <= kMostPeriodsAway * box.length(axis))) {
    throw InputError(place.at(line) + "expected a position within 2^26 periods of the box along " +
                     std::string(1, "xyz"[axis]) + " (wrapped into it, one farther keeps under " +
                     "half its digits), got " + format_number(x));
  }
  return box.wrap(axis, x);
}

void fill_frame(const AtomLines& a, const std::vector<std::size_t>& order, const AtomColumns& c,
                const SnapshotHeader& h, double radius, SnapshotAtoms& out) {
  Frame& f = out.frame;
  const auto n = static_cast<Eigen::Index>(order.size());
  f.resize(n, 3);
  std::vector<ValueTable<double>*> vectors;
  for (const VectorColumn& v : c.vectors)
    vectors.push_back(&f.add(v.name).as<ValueTable<double>>());
  std::vector<Values<double>*> kept;
  for (const KeptColumn& k : c.kept) kept.push_back(&f.particles.add<Values<double>>(k.property));
  const std::size_t m = a.read.size();
  for (Eigen::Index row = 0; row < n; ++row) {
    const std::size_t line = order[static_cast<std::size_t>(row)];
    const double* v = &a.values[line * m];
    out.lines.push_back(a.lines[line]);
    f.id()[row] = a.ids[line];
    f.species()[row] = a.types[line] - 1;
    for (int axis = 0; axis < 3; ++axis)
      f.position()(row, axis) =
          position(*v++, c.coordinate[axis], h.box.container, axis, h.place, a.lines[line]);
    f.radius()[row] = c.size < 0 ? radius : c.diameter ? 0.5 * *v++ : *v++;
    for (ValueTable<double>* vector : vectors)
      for (Eigen::Index axis = 0; axis < 3; ++axis) (*vector)(row, axis) = *v++;
    for (Values<double>* column : kept) (*column)[row] = *v++;
  }
}

}  // namespace

SnapshotAtoms read_atoms(const SnapshotHeader& header, const AtomColumns& columns, double radius,
                         TextLines& lines) {
  AtomLines a;
  choose_columns(columns, a);
  std::string line;
  for (std::int64_t k = 0; k < header.atoms; ++k) {
    next_line_of(header.place, lines, line);
    parse_line(line, header.place, lines.number(), columns, a);
  }
  SnapshotAtoms out;
  out.precision = a.precision;
  fill_frame(a, id_order(a, header.place), columns, header, radius, out);
  return out;
}

}  // namespace granpipe::lammps_dump
