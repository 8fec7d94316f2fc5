#include "dump_index.hpp"

#include "granpipe/errors.hpp"
#include "granpipe/text_words.hpp"
#include "not_a_dump.hpp"
#include "snapshot_header.hpp"

namespace granpipe::lammps_dump {

namespace {

// Reads past blank lines to the next that is not blank, noting where it starts; false at
// the end of the file.
bool next_filled_line(TextLines& lines, std::string& line, SnapshotStart& start) {
  do {
    start.offset = lines.offset();
    start.line_before = lines.number();
    if (!lines.next(line)) return false;
  } while (trimmed(line).empty());
  return true;
}

std::string expected_atoms(const SnapshotHeader& h, const DumpKind& kind) {
  const std::string count = std::string(kind.count_item).substr(std::string("ITEM: ").size());
  return "expected " + std::to_string(h.atoms) + " " + kind.row + " lines (" + count + ", line " +
         std::to_string(h.atoms_line) + "), got ";
}

// Over the atom (entry) lines, counting them.
void skip_atoms(const SnapshotHeader& h, TextLines& lines, const DumpKind& kind) {
  std::string line;
  for (std::int64_t k = 0; k < h.atoms; ++k) {
    next_line_of(h.place, lines, line);
    if (line.starts_with("ITEM:")) {
      throw InputError(h.place.at(lines.number()) + expected_atoms(h, kind) + std::to_string(k) +
                       " before " + quoted(trimmed(line)));
    }
    if (trimmed(line).empty()) {
      throw InputError(h.place.at(lines.number()) + "expected an " + kind.row +
                       " line, got an empty line");
    }
  }
}

void check_columns(const DumpIndex& index, const SnapshotHeader& h) {
  if (h.columns == index.columns) return;
  std::string got;
  for (const auto& c : h.columns) got += (got.empty() ? "" : " ") + c;
  std::string first;
  for (const auto& c : index.columns) first += (first.empty() ? "" : " ") + c;
  throw InputError(h.place.at(h.columns_line) + "expected the columns of the first snapshot (\"" +
                   first + "\"), got \"" + got + "\"");
}

// The first line must open a snapshot; otherwise say what the file is.
void check_is_dump(TextLines& lines, bool found, const std::string& line) {
  const std::string expected = "expected a LAMMPS dump (starting \"ITEM: TIMESTEP\"), got ";
  if (!found && lines.ended_early()) {
    throw InputError(lines.path() + ": " + expected +
                     "gzip data that end before the first line (the file was cut)");
  }
  if (!found) throw InputError(lines.path() + ": " + expected + "an empty file");
  if (line.starts_with("ITEM:")) return;
  const long number = lines.number();
  throw InputError(lines.path() + ": line " + std::to_string(number) + ": " + expected +
                   what_the_file_is(lines, line));
}

// Snapshots in the order of their timesteps, each once. A dump appended to by a restarted
// run, or one across a reset_timestep, repeats timesteps: read as it was, its frames went
// back in time and a contact dump joined by timestep gave a repeated snapshot the contacts
// of the first one.
void check_timestep_follows(const DumpIndex& index, const SnapshotHeader& h,
                            const SnapshotStart& start) {
  if (index.snapshots.empty()) return;
  const SnapshotStart& before = index.snapshots.back();
  if (start.timestep > before.timestep) return;
  throw InputError(h.place.at(h.place.first_line + 1) + "expected a timestep after " +
                   std::to_string(before.timestep) + " (the snapshot before, from line " +
                   std::to_string(before.line_before + 1) + "), got " +
                   std::to_string(start.timestep) +
                   ": timesteps that repeat or go back (a run appended to its dump after a "
                   "restart, or a reset_timestep?)");
}

}  // namespace

DumpIndex index_snapshots(TextLines& lines, const DumpKind& kind) {
  DumpIndex index;
  std::string line;
  SnapshotStart start;
  bool found = next_filled_line(lines, line, start);
  check_is_dump(lines, found, line);
  std::optional<SnapshotHeader> last;
  for (; found; found = next_filled_line(lines, line, start)) {
    if (last && !lines.cut() && !line.starts_with("ITEM:")) {
      throw InputError(last->place.at(lines.number()) + expected_atoms(*last, kind) +
                       "more: " + quoted(trimmed(line)));
    }
    try {
      // The file ends inside the first line of a snapshot.
      if (lines.cut()) throw SnapshotCut{SnapshotPlace{lines.path(), lines.number()}};
      last = read_header(lines.path(), lines, line, kind);
      if (index.snapshots.empty()) {
        index.columns = last->columns;
        index.columns_at = last->place.at(last->columns_line);
      }
      check_columns(index, *last);
      skip_atoms(*last, lines, kind);
    } catch (const SnapshotCut& cut) {
      index.cut = cut.place;
      break;
    }
    start.timestep = *last->place.timestep;
    check_timestep_follows(index, *last, start);
    index.snapshots.push_back(start);
  }
  index.ended_early = lines.ended_early();
  if (!index.ended_early) lines.check_nothing_follows();
  return index;
}

DumpIndex complete_snapshots(TextLines& lines, const DumpKind& kind) {
  DumpIndex index = index_snapshots(lines, kind);
  if (index.snapshots.empty()) {
    throw InputError(lines.path() +
                     ": expected a complete snapshot, got none: the file ends "
                     "inside " +
                     index.cut->name());
  }
  return index;
}

}  // namespace granpipe::lammps_dump
