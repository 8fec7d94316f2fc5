#pragma once
// Every vertex of the additively weighted Voronoi diagram of spheres, by construction. With
// g_i(c, rho) = -2 c.x_i - 2 rho r_i + |x_i|^2 - r_i^2, a sphere (c, rho) touches sphere i
// where |c|^2 - rho^2 + g_i = 0 and overlaps none where g_i is least of all there: a
// vertex lies on an edge of the lower envelope of the affine functions g_i over (c, rho),
// the power diagram of the points (x_i, r_i) in 4D with weights 2 r_i^2. Each edge is dual
// to a 3-face of their regular triangulation, bounded by the two full cells that share it:
// the face's four spheres' tangent sphere is a vertex when it overlaps neither of the
// cells' opposite spheres. Exact at any radius ratio; about fifty times the cost of the 3D
// Delaunay triangulation (docs/notes/pores-apollonius.md).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "tangent_sphere.hpp"

namespace granpipe::pores {

struct LiftedVertex {
  std::array<std::uint32_t, 4> spheres;  // rows of `centres`, sorted
  TangentSphere sphere;                  // tangent_sphere's root
};

// The vertices, overlaps within `length` not counting; a vertex of five or more spheres
// on one sphere comes once for each face that gives it. Centres with radii an affine
// function of them lift into a hyperplane: the triangulation's full cells are then the
// faces, unbounded along the edge.
std::vector<LiftedVertex> lifted_vertices(const std::vector<Eigen::Vector3d>& centres,
                                          const std::vector<double>& radii, double length);

}  // namespace granpipe::pores
