#pragma once
// The atom lines of one snapshot (after its header, snapshot_header.hpp) as a frame: rows
// in id order whatever the file's order, positions in the box (scaled ones converted,
// periodic ones wrapped into it), radii from the radius or diameter column.
#include <vector>

#include "atom_columns.hpp"
#include "granpipe/frame.hpp"
#include "position_precision.hpp"
#include "snapshot_header.hpp"
#include "text_lines.hpp"

namespace granpipe::lammps_dump {

struct SnapshotAtoms {
  Frame frame;                  // step, time and container left to the caller
  std::vector<long> lines;      // the line of each row, for messages
  PositionPrecision precision;  // of the position columns as printed
};

// `radius`: every atom's radius when the columns hold none. InputError starting with the
// file, timestep and line for a line with another number of values, a value that is not a
// number (or not a finite one where the frame needs one), a radius <= 0, a type < 1, or an
// atom id given twice; SnapshotCut when the file ends inside the atom lines.
SnapshotAtoms read_atoms(const SnapshotHeader& header, const AtomColumns& columns, double radius,
                         TextLines& lines);

}  // namespace granpipe::lammps_dump
