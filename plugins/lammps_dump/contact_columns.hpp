#pragma once
// What the columns of a `dump local` of contacts hold. The file names them only as the
// dump command listed them (c_pairs[1] c_pairs[2] ...), so the pipeline gives the keywords
// of the computes that made them:
//   LIGGGHTS `compute pair/gran/local` and `compute wall/gran/local`: keywords among pos,
//     vel, id, force, force_normal, force_tangential, torque, contactArea, delta, heatFlux;
//     whatever their order in the command, LIGGGHTS writes their values in that order, each
//     keyword giving 6, 6, 3, 3, 3, 3, 3, 1, 1, 1 columns (id: the two atom ids and a
//     periodic flag; for a wall, the mesh, the triangle and the atom);
//   LAMMPS `compute property/local patom1 patom2` and `compute pair/local`: one keyword
//     per column, in the dump's order: patom1, patom2, fx, fy, fz (the normal force of a
//     granular pair style on patom1), p1, p2, p3 (its tangential force), dist, and the
//     others kept out (eng, force, ptype1, ptype2, p4 ... p10).
#include <array>
#include <string>
#include <vector>

#include "granpipe/params.hpp"

namespace granpipe::lammps_dump {

enum class ContactFormat { Liggghts, Lammps };
inline ChoiceNames<ContactFormat> choice_names(ContactFormat) {
  return {{"liggghts", ContactFormat::Liggghts}, {"lammps", ContactFormat::Lammps}};
}

// Dump columns (0-based) of each value; -1 where the dump has none.
struct ContactColumns {
  std::size_t count = 0;   // values on every entry line
  int id1 = -1, id2 = -1;  // the atoms; a wall contact has its atom in id1 and no id2
  std::array<int, 3> normal{-1, -1, -1};      // normal force on atom 1 from its partner
  std::array<int, 3> force{-1, -1, -1};       // the whole contact force on atom 1
  std::array<int, 3> tangential{-1, -1, -1};  // tangential force on atom 1
  int overlap = -1;                           // LIGGGHTS delta
  int distance = -1;                          // LAMMPS dist: overlap = R1 + R2 - dist
  std::array<int, 3> point{-1, -1, -1};       // a LIGGGHTS wall contact's point (its pos)
};

// `keywords`: the compute's (LIGGGHTS) or one per column (LAMMPS); `wall`: the file of
// compute wall/gran/local. `param` names the parameter in messages. InputError for an
// unknown or repeated keyword, or one the contacts need (the ids and the normal force)
// missing.
ContactColumns contact_columns(ContactFormat format, const std::vector<std::string>& keywords,
                               bool wall, const std::string& param);

}  // namespace granpipe::lammps_dump
