#pragma once
// What the columns of "ITEM: ATOMS id type x y z radius ..." hold, in any order, as
// `dump custom` names them:
//   id (required), type (species = type - 1; 0 without it),
//   positions per axis: x (as written), xu (unwrapped), xs (scaled by the box), xsu
//     (scaled and unwrapped), the first of these found;
//   radius, or diameter (halved);
//   vx vy vz, omegax omegay omegaz, fx fy fz, tqx tqy tqz: the frame's velocity,
//     angular_velocity, force and torque (all three or none);
// and any other numeric column kept as a real particle column of its name, with "[k]" as
// "_k" (c_stress[1] -> c_stress_1).
#include <array>
#include <string>
#include <vector>

#include "granpipe/property.hpp"

namespace granpipe::lammps_dump {

// The start of a refusal of a 2D run's dump (a missing z column here, LAMMPS's flat box in
// the source): granpipe's frames from LAMMPS are 3D.
inline constexpr const char* kReads3d =
    "expected a 3D dump (granpipe's LAMMPS readers read 3D dumps), got ";

// How a position column relates to the box.
enum class Coordinate { Plain, Unwrapped, Scaled, ScaledUnwrapped };

// A column of the frame made from three of the dump's (velocity from vx vy vz).
struct VectorColumn {
  std::string name;       // the frame's standard column
  std::array<int, 3> at;  // the dump's column of each component
};

// A dump column kept as it is.
struct KeptColumn {
  Property property;
  int at = 0;
};

struct AtomColumns {
  std::size_t count = 0;  // values on every atom line
  int id = -1, type = -1;
  std::array<int, 3> position{-1, -1, -1};
  std::array<Coordinate, 3> coordinate{};
  int size = -1;  // radius or diameter; -1: none
  bool diameter = false;
  std::vector<VectorColumn> vectors;
  std::vector<KeptColumn> kept;
  std::vector<std::string> names;  // as in the file

  // The frame columns beyond the required ones: vectors and kept columns.
  std::vector<Property> properties() const;
};

// InputError starting with `at` (file, timestep, line) for a required column that is
// missing, a column given twice, a vector without all its components, or two columns
// kept under one name.
AtomColumns parse_atom_columns(const std::vector<std::string>& names, const std::string& at);

}  // namespace granpipe::lammps_dump
