#pragma once
// Rectangular (orthogonal) unit cells of the 2D and 3D lattices, in units of the
// nearest-neighbour distance. The last axis is vertical (gravity along -y in 2D, -z in
// 3D): close-packed rows (2D) and planes (hcp) are horizontal.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace granpipe::lattice {

struct UnitCell {
  int dim = 3;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // edge lengths (first dim entries)
  std::vector<Eigen::Vector3d> basis;              // sites in the cell
};

// The names accepted by unit_cell(), 2D ones first.
const std::vector<std::string>& lattice_names();

// square, triangular (2D); sc, bcc, fcc, hcp (3D). Throws InternalError on another name.
UnitCell unit_cell(const std::string& name);

}  // namespace granpipe::lattice
