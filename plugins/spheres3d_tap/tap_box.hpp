#pragma once
// The vessel of the 3D tapping model: a square box of side L in x and y over a flat,
// impassable bottom at z = 0, open at the top. Its sides are either fixed walls (the
// paper's F.B.C.) or periodic (P.B.C.). All spheres have one radius R.
#include <Eigen/Core>
#include <vector>

#include "granpipe/container.hpp"
#include "granpipe/params.hpp"

namespace granpipe::spheres3d_tap {

enum class Sides : unsigned char { Walls, Periodic };
// The names pipelines give them (parameter sides).
inline ChoiceNames<Sides> choice_names(Sides) {
  return {{"periodic", Sides::Periodic}, {"walls", Sides::Walls}};
}

// A plane a sphere's centre may not cross: n . x >= offset, n the unit normal into the box.
// For a wall at x = 0 that is n = (1, 0, 0), offset R (the centre keeps R from it).
struct CentrePlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;
  int label = 0;  // the Wall it stands for (granpipe::Wall), for support labels
};

struct TapBox {
  double side = 32.0;
  double radius = 1.0;
  Sides sides = Sides::Periodic;

  bool periodic() const { return sides == Sides::Periodic; }
  // The bottom and, with walls, the four sides, as planes of the centres.
  std::vector<CentrePlane> centre_planes() const;
  // The frame's container: [0, L]^2 x [0, top], open at the top.
  Container container(double top) const;
  // x and y brought into [0, L) on a periodic box (unchanged with walls).
  Eigen::Vector3d wrap(Eigen::Vector3d x) const;
};

}  // namespace granpipe::spheres3d_tap
