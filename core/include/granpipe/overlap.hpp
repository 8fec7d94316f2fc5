#pragma once
// Exact overlap geometry of disks and spheres with axis-aligned rectangles and boxes,
// and their cuts by lines and planes: what a packing fraction needs to count the
// particles a region's boundary cuts, and what stereological profiles need.
// Everything is closed form (no quadrature): accurate to a few ulps of r^2 or r^3.
#include <Eigen/Core>

namespace granpipe::overlap {

// Area of a disk of radius r (2D) or volume of a ball of radius r (3D).
double ball_measure(int dim, double r);

// Radius of the cut of a disk or sphere of radius r by a line or plane at distance h
// from its centre: sqrt(r^2 - h^2), 0 when |h| >= r.
double cut_radius(double r, double h);

// Area of the part {y >= h} of a disk of radius r centred at the origin.
double disk_segment_area(double r, double h);

// Volume of the part {z >= h} of a sphere of radius r centred at the origin.
double sphere_cap_volume(double r, double h);

// Length of [c - w, c + w] ∩ [x0, x1]: the part of a chord of half-width w centred at c
// that lies in an interval.
double interval_overlap(double c, double w, double x0, double x1);

// Area of the disk (centre c, radius r) ∩ the rectangle [lo, hi].
double disk_rectangle_area(const Eigen::Vector2d& c, double r, const Eigen::Vector2d& lo,
                           const Eigen::Vector2d& hi);

// Volume of the sphere (centre c, radius r) ∩ the box [lo, hi].
double sphere_box_volume(const Eigen::Vector3d& c, double r, const Eigen::Vector3d& lo,
                         const Eigen::Vector3d& hi);

// Either of the two above by dimension; c, lo and hi point to `dim` coordinates.
double ball_box_measure(int dim, const double* c, double r, const double* lo, const double* hi);

}  // namespace granpipe::overlap
