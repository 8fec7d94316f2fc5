#include "snapshot_header.hpp"

#include <cmath>
#include <string_view>

#include "granpipe/errors.hpp"
#include "granpipe/text_words.hpp"

namespace granpipe::lammps_dump {

const DumpKind kAtomDump{"ITEM: NUMBER OF ATOMS", "ITEM: ATOMS", "atom",
                         "a dump local (contacts, bonds), not a dump of atoms"};
const DumpKind kLocalDump{"ITEM: NUMBER OF ENTRIES", "ITEM: ENTRIES", "entry",
                          "a dump of atoms, not a dump local"};

namespace {

// Whether `line` is the item `name`, alone or followed by its words ("ITEM: ATOMS id ...").
bool is_item(std::string_view line, std::string_view name) {
  return line.starts_with(name) && (line.size() == name.size() || line[name.size()] == ' ' ||
                                    trimmed(line).size() == name.size());
}

[[noreturn]] void refuse_item(const SnapshotPlace& place, const TextLines& lines,
                              const std::string& item, std::string_view wanted,
                              const DumpKind& kind) {
  std::string what = quoted(trimmed(item));
  const DumpKind& other = &kind == &kAtomDump ? kLocalDump : kAtomDump;
  if (trimmed(item) == other.count_item) what += std::string(": ") + kind.other;
  throw InputError(place.at(lines.number()) + "expected \"" + std::string(wanted) + "\", got " +
                   what);
}

// The line just read must be this item.
void expect_item(const SnapshotPlace& place, const TextLines& lines, const std::string& item,
                 std::string_view wanted, const DumpKind& kind) {
  if (!is_item(item, wanted)) refuse_item(place, lines, item, wanted, kind);
}

// The value line after an item.
std::string value_line(const SnapshotPlace& place, TextLines& lines) {
  std::string line;
  next_line_of(place, lines, line);
  return line;
}

std::int64_t whole_value(const SnapshotPlace& place, TextLines& lines, const char* what) {
  const std::string line = value_line(place, lines);
  const auto w = words(line);
  const auto value = w.size() == 1 ? whole_number(w[0]) : std::nullopt;
  if (!value || *value < 0) {
    throw InputError(place.at(lines.number()) + "expected " + what + ", a whole number >= 0, got " +
                     quoted(line));
  }
  return *value;
}

double time_value(const SnapshotPlace& place, TextLines& lines) {
  const std::string line = value_line(place, lines);
  const auto w = words(line);
  const auto value = w.size() == 1 ? real_number(w[0]) : std::nullopt;
  if (!value || !std::isfinite(*value)) {
    throw InputError(place.at(lines.number()) + "expected the time, a finite number, got " +
                     quoted(line));
  }
  return *value;
}

// The optional items before TIMESTEP; leaves `item` at the first line after them.
void read_units_and_time(SnapshotHeader& h, TextLines& lines, std::string& item) {
  if (is_item(item, "ITEM: UNITS")) {
    value_line(h.place, lines);  // lj, si, ...: granpipe's units are the file's
    next_line_of(h.place, lines, item);
  }
  if (is_item(item, "ITEM: TIME")) {
    h.time = time_value(h.place, lines);
    next_line_of(h.place, lines, item);
  }
}

}  // namespace

SnapshotHeader read_header(const std::string& file, TextLines& lines, std::string item,
                           const DumpKind& kind) {
  SnapshotHeader h;
  h.place = SnapshotPlace{file, lines.number()};
  read_units_and_time(h, lines, item);
  expect_item(h.place, lines, item, "ITEM: TIMESTEP", kind);
  h.place.timestep = whole_value(h.place, lines, "the timestep");

  next_line_of(h.place, lines, item);
  expect_item(h.place, lines, item, kind.count_item, kind);
  h.atoms_line = lines.number();
  h.atoms = whole_value(h.place, lines,
                        &kind == &kAtomDump ? "the number of atoms" : "the number of entries");

  next_line_of(h.place, lines, item);
  expect_item(h.place, lines, item, "ITEM: BOX BOUNDS", kind);
  h.box = read_box(item, h.place, lines);

  next_line_of(h.place, lines, item);
  const std::string_view columns_item = kind.columns_item;
  expect_item(h.place, lines, item, columns_item, kind);
  h.columns_line = lines.number();
  for (std::string_view w : words(std::string_view(item).substr(columns_item.size())))
    h.columns.emplace_back(w);
  return h;
}

}  // namespace granpipe::lammps_dump
