#include "box_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/errors.hpp"
#include "granpipe/text_words.hpp"

namespace granpipe::lammps_dump {

namespace {

constexpr std::string_view kItem = "ITEM: BOX BOUNDS";

// LAMMPS's boundary styles: p periodic (always on both sides), f fixed, s shrink-wrapped,
// m shrink-wrapped with a minimum.
bool is_flag_pair(std::string_view w) {
  auto style = [](char c) { return c == 'f' || c == 's' || c == 'm'; };
  return w == "pp" || (w.size() == 2 && style(w[0]) && style(w[1]));
}

bool is_triclinic(const std::vector<std::string_view>& flags) {
  return std::any_of(flags.begin(), flags.end(),
                     [](std::string_view w) { return w == "xy" || w == "abc"; });
}

void read_extent(const SnapshotPlace& place, TextLines& lines, int axis, Container& box) {
  std::string line;
  next_line_of(place, lines, line);
  const auto w = words(line);
  const char* name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
  const auto expected = place.at(lines.number()) + "expected \"lo hi\" of the box along " + name +
                        " (two numbers, lo < hi), got ";
  if (w.size() == 3) {
    throw InputError(expected + quoted(line) + ": a triclinic box's tilt, not supported");
  }
  const auto lo = w.size() == 2 ? real_number(w[0]) : std::nullopt;
  const auto hi = w.size() == 2 ? real_number(w[1]) : std::nullopt;
  if (!lo || !hi || !std::isfinite(*lo) || !std::isfinite(*hi) || !(*lo < *hi)) {
    throw InputError(expected + quoted(line));
  }
  box.lo[axis] = *lo;
  box.hi[axis] = *hi;
}

}  // namespace

DumpBox read_box(const std::string& item, const SnapshotPlace& place, TextLines& lines) {
  DumpBox box{Container{}, lines.number()};
  const auto flags = words(std::string_view(item).substr(kItem.size()));
  if (is_triclinic(flags)) {
    throw InputError(place.at(box.line) +
                     "expected an orthogonal box (\"ITEM: BOX BOUNDS pp pp ff\"), got a "
                     "triclinic one (" +
                     quoted(trimmed(item)) + "): granpipe's containers have right angles");
  }
  if (flags.size() != 3 || !std::all_of(flags.begin(), flags.end(), is_flag_pair)) {
    throw InputError(place.at(box.line) +
                     "expected three pairs of boundary flags after BOX BOUNDS (p, f, s or m, "
                     "e.g. \"pp pp ff\"), got " +
                     quoted(trimmed(item)));
  }
  for (int a = 0; a < 3; ++a) {
    const Boundary side = flags[a] == "pp" ? Boundary::Periodic : Boundary::Open;
    box.container.boundary[a] = {side, side};
    read_extent(place, lines, a, box.container);
  }
  return box;
}

}  // namespace granpipe::lammps_dump
