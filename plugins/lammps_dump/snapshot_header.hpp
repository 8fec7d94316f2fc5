#pragma once
// The items that open each snapshot of a LAMMPS or LIGGGHTS text dump (`dump custom`,
// `dump atom`), in the order LAMMPS writes them:
//   ITEM: UNITS, ITEM: TIME   (each with its value line; only with dump_modify units/time)
//   ITEM: TIMESTEP            the step
//   ITEM: NUMBER OF ATOMS     the atom lines that follow the header
//   ITEM: BOX BOUNDS pp pp ff and one "lo hi" line per axis (box_bounds.hpp)
//   ITEM: ATOMS id type x ... the column names (atom_columns.hpp)
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "box_bounds.hpp"
#include "snapshot_place.hpp"
#include "text_lines.hpp"

namespace granpipe::lammps_dump {

struct SnapshotHeader {
  SnapshotPlace place;
  std::optional<double> time;  // ITEM: TIME
  std::int64_t atoms = 0;
  long atoms_line = 0;  // of "ITEM: NUMBER OF ATOMS"
  DumpBox box;
  std::vector<std::string> columns;
  long columns_line = 0;  // of "ITEM: ATOMS"
};

// Reads the header whose first line, `item` ("ITEM: ..."), was the line last read from
// `lines`. InputError starting with the file, timestep and line for an item out of place
// or a value that is not what it should be; SnapshotCut when the file ends inside it.
SnapshotHeader read_header(const std::string& file, TextLines& lines, std::string item);

}  // namespace granpipe::lammps_dump
