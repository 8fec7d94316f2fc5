#pragma once
// A `dump local` of contacts (LIGGGHTS pair/gran/local or wall/gran/local, LAMMPS
// pair/local with property/local), joined to the atom dump's frames by TIMESTEP: each
// entry becomes a contact row of the frame whose snapshot has its timestep, its atoms
// found by id among that snapshot's.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "contact_columns.hpp"
#include "dump_index.hpp"
#include "granpipe/contact_rows.hpp"
#include "granpipe/frame.hpp"
#include "text_lines.hpp"

namespace granpipe::lammps_dump {

class ContactDump {
 public:
  // `param` names the file's parameter in messages. Indexes the file (InputError as the
  // atom dump's reader gives them, for a dump local).
  ContactDump(std::string path, ContactColumns columns, bool wall, const std::string& param);

  // InputError for a snapshot whose timestep no snapshot of the atom dump has (past the
  // last complete one of an atom dump that was cut, snapshots are let be).
  void check_timesteps(const DumpIndex& atoms, const std::string& atom_file) const;
  // Appends the contacts of the snapshot of the frame's step. InputError for a frame whose
  // step the file has no snapshot of, an entry line with other values than the columns
  // say, an atom id the frame does not hold, a pair of atoms apart by more than
  // `rounding` (how far off the frame's centre distances may be) or an atom apart from its
  // wall (at the entry's point where given: the base of a vibrated bed moves, and only the
  // entry says where it was; a point off the wall's normal, of a wall not stated), an
  // overlap column the positions contradict, or a pair's normal force off the line of its
  // centres.
  void read(const Frame& frame, const std::string& frame_place, double rounding,
            std::vector<ContactRow>& rows);
  bool has_tangential() const { return columns_.tangential[0] >= 0 || columns_.force[0] >= 0; }
  const std::string& path() const { return lines_.path(); }

 private:
  TextLines lines_;
  DumpIndex index_;
  ContactColumns columns_;
  bool wall_;
  std::string param_;
  std::unordered_map<std::int64_t, std::size_t> by_timestep_;
};

}  // namespace granpipe::lammps_dump
