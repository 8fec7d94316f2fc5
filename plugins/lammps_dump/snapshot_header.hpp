#pragma once
// The items that open each snapshot of a LAMMPS or LIGGGHTS text dump (`dump custom`,
// `dump atom`), in the order LAMMPS writes them:
//   ITEM: UNITS, ITEM: TIME   (each with its value line; only with dump_modify units/time)
//   ITEM: TIMESTEP            the step
//   ITEM: NUMBER OF ATOMS     the atom lines that follow the header
//   ITEM: BOX BOUNDS pp pp ff and one "lo hi" line per axis (box_bounds.hpp)
//   ITEM: ATOMS id type x ... the column names (atom_columns.hpp)
// and of a `dump local` (contacts, bonds), whose items name entries instead of atoms:
//   ITEM: NUMBER OF ENTRIES, ITEM: ENTRIES c_pairs[1] ...
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "box_bounds.hpp"
#include "snapshot_place.hpp"
#include "text_lines.hpp"

namespace granpipe::lammps_dump {

// What the rows of a dump are: atoms (dump custom, dump atom) or entries (dump local).
struct DumpKind {
  const char* count_item;    // "ITEM: NUMBER OF ATOMS"
  const char* columns_item;  // "ITEM: ATOMS"
  const char* row;           // "atom", for messages
  const char* other;         // what a file of the other kind is, for its refusal
};
extern const DumpKind kAtomDump, kLocalDump;

struct SnapshotHeader {
  SnapshotPlace place;
  std::optional<double> time;  // ITEM: TIME
  std::int64_t atoms = 0;      // rows: atoms, or entries of a dump local
  long atoms_line = 0;         // of "ITEM: NUMBER OF ATOMS" (or ENTRIES)
  DumpBox box;
  std::vector<std::string> columns;
  long columns_line = 0;  // of "ITEM: ATOMS"
};

// Reads the header whose first line, `item` ("ITEM: ..."), was the line last read from
// `lines`. InputError starting with the file, timestep and line for an item out of place
// or a value that is not what it should be; SnapshotCut when the file ends inside it.
SnapshotHeader read_header(const std::string& file, TextLines& lines, std::string item,
                           const DumpKind& kind = kAtomDump);

}  // namespace granpipe::lammps_dump
