#pragma once
// A source's contacts as rows, before they become the frame's contact table: one row per
// contact, with the forces on particle i. Sources that read or compute contact forces (the
// dem engine, LAMMPS local dumps) gather rows in their own order and fill the table once.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "granpipe/frame.hpp"

namespace granpipe {

struct ContactRow {
  std::int64_t i = 0, j = 0;  // frame rows; j = partner::wall(w) for a wall contact
  double overlap = 0.0;
  Eigen::Vector3d normal, tangential, point;  // forces on i; tangential unused without it
};

// The frame's contact table, in the rows' order: contact_i, contact_j, overlap,
// normal_force, point, and tangential_force when `tangential`.
void fill_contact_table(const std::vector<ContactRow>& rows, bool tangential, Frame& frame);

}  // namespace granpipe
