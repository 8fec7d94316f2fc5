#pragma once
// The particles of a LAMMPS data file written for atom_style sphere (read_data/write_data).
// As LAMMPS reads it: the first line is a title; the header, up to the first section,
// gives "N atoms" and the box ("lo hi xlo xhi", y and z alike); the "Atoms" section's lines
// are "id type diameter density x y z", with three image flags after them in files from
// write_data, and a "# ..." comment allowed at the end of any line. The particles come out
// in id order, the species as type - 1, in the box with open sides (the walls and periodic
// sides live in the input script: the source states them).
//
// Another atom style would be read as nonsense (atom_style full's "id molecule type q x y
// z" has the same 7 columns: the molecule as the type, the type as the diameter), so the
// style LAMMPS writes after the section name ("Atoms # sphere") must be named, and sphere.
#include <istream>
#include <string>

#include "granpipe/frame.hpp"

namespace granpipe::lammps_data {

// InputError starting with `where` (the file) and the line, for anything else: another
// atom style or none named, a malformed line, an atom count other than the header's, an id
// given twice, a box line missing, malformed or triclinic, a LAMMPS dump (named as one: its
// first line would pass for a title).
Frame read_atoms(std::istream& in, const std::string& where);

}  // namespace granpipe::lammps_data
