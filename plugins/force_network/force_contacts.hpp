#pragma once
// Which contacts of a frame carry force, and which enter the force statistics.
//
// Edges of the force networks are particle–particle contacts with |F_n| > min_force
// (walls are not particles, so wall contacts never join two particles). The samples of
// <F_n>, the PDF and F(r) are the edges, plus the wall contacts with |F_n| > min_force
// when `walls` is set. |F_n| is the length of the contact's normal_force vector.
#include <cmath>
#include <string>
#include <vector>

#include "granpipe/frame.hpp"

namespace granpipe::force_network {

struct ForceSettings {
  double min_force = 0.0;  // an edge needs |F_n| > min_force
  bool walls = false;      // wall contacts join the samples (never the networks)
};

struct ForceContacts {
  Eigen::ArrayXd magnitude;           // |F_n| of every contact row
  std::vector<Eigen::Index> edges;    // rows: particle–particle, |F_n| > min_force
  std::vector<Eigen::Index> samples;  // rows of the statistics, ascending
  double mean = std::nan("");         // <F_n> over the samples; NaN (undefined) when none
  // Particle–particle contacts with |F_n| > 0 (granpipe/loaded_pair_contacts.hpp): the
  // count that picks the paper's frame, whatever min_force is (the mst analyzer counts the
  // same way).
  long loaded = 0;
};

// Throws InputError after `where` when the frame has no contact table, the table lacks
// normal_force, a row joins a particle to itself or a normal force is NaN or infinite.
ForceContacts force_contacts(const Frame& frame, const ForceSettings& settings,
                             const std::string& where);

// f = |F_n| / <F_n> of the given rows, normalised by `mean` (0 when mean is not > 0).
std::vector<double> scaled_forces(const ForceContacts& forces,
                                  const std::vector<Eigen::Index>& rows, double mean);

// The contact points (column `point`) of the given rows, one per row. Throws InputError
// after `where` when the contacts have no point column.
Coordinates contact_points(const Frame& frame, const std::vector<Eigen::Index>& rows,
                           const std::string& where);

}  // namespace granpipe::force_network
