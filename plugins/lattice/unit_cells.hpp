#pragma once
// Rectangular (orthogonal) unit cells of the 2D and 3D lattices, in units of the
// nearest-neighbour distance. The last axis is vertical (gravity along -y in 2D, -z in
// 3D): close-packed rows (2D) and planes (hcp) are horizontal.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "granpipe/params.hpp"

namespace granpipe::lattice {

struct UnitCell {
  int dim = 3;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // edge lengths (first dim entries)
  std::vector<Eigen::Vector3d> basis;              // sites in the cell
};

enum class Lattice : std::uint8_t { Square, Triangular, Sc, Bcc, Fcc, Hcp };
// Their names in pipelines, 2D ones first.
inline ChoiceNames<Lattice> choice_names(Lattice) {
  return {{"square", Lattice::Square}, {"triangular", Lattice::Triangular},
          {"sc", Lattice::Sc},         {"bcc", Lattice::Bcc},
          {"fcc", Lattice::Fcc},       {"hcp", Lattice::Hcp}};
}

// square, triangular (2D); sc, bcc, fcc, hcp (3D).
UnitCell unit_cell(Lattice lattice);

}  // namespace granpipe::lattice
