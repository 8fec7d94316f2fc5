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

// The frame's contact table of `count` rows, written row by row (a source with many
// contacts need not hold them all as rows too): contact_i, contact_j, overlap,
// normal_force, point, and tangential_force when `tangential`.
class ContactTableWriter {
 public:
  ContactTableWriter(Frame& frame, Eigen::Index count, bool tangential);
  void set(Eigen::Index r, const ContactRow& row);

 private:
  Frame& frame_;
  PropertyTable& table_;  // made first: the columns below are its
  Eigen::ArrayXd& overlap_;
  Coordinates &normal_, &point_;
  Coordinates* tangential_;
};

// The table from rows, in their order.
void fill_contact_table(const std::vector<ContactRow>& rows, bool tangential, Frame& frame);

}  // namespace granpipe
