#pragma once
// The pore of four spheres of unequal radii: the sphere tangent to all four from outside
// (the vertex of their additively weighted Voronoi diagram, Apollonius' problem), centre c
// and radius rho with |c - x_i| = r_i + rho.
#include <Eigen/Core>
#include <array>
#include <optional>

namespace granpipe::pores {

struct TangentSphere {
  Eigen::Vector3d centre;
  double radius = 0.0;  // negative where the four spheres overlap so much that it is no gap
};

// Subtracting the first equation from the others leaves a linear system, c = A + rho B,
// and the first equation then a quadratic in rho. Of its roots, those with r_i + rho > 0
// for all four (the squared equations' true solutions) are tangent spheres; the smallest
// is the one in the gap between the four, the other (when there is one) touches them from
// beyond. Nothing when no root is a true solution (a sphere hidden inside the others, which
// no sphere outside them reaches) or the centres span no volume.
std::optional<TangentSphere> tangent_sphere(const std::array<Eigen::Vector3d, 4>& centres,
                                            const std::array<double, 4>& radii);

}  // namespace granpipe::pores
