#pragma once
// The particles of a LAMMPS data file written for atom_style sphere (read_data/write_data).
// As LAMMPS reads it: the first line is a title; the header, up to the first section,
// gives "N atoms"; the "Atoms" section's lines are "id type diameter density x y z", with
// three image flags after them in files from write_data, and a "# ..." comment allowed at
// the end of any line. The particles come out in id order, the species as type - 1.
//
// Another atom style would be read as nonsense (atom_style full's "id molecule type q x y
// z" has the same 7 columns: the molecule as the type, the type as the diameter), so the
// style LAMMPS writes after the section name ("Atoms # sphere") must be sphere; a file
// without it must have 7 or 10 columns per atom.
#include <istream>
#include <string>

#include "granpipe/frame.hpp"

namespace granpipe::lammps_data {

// InputError starting with `where` (the file) and the line, for anything else: another
// atom style, a malformed line, an atom count other than the header's, an id given twice,
// a LAMMPS dump (named as one: its first line would pass for a title).
Frame read_atoms(std::istream& in, const std::string& where);

}  // namespace granpipe::lammps_data
