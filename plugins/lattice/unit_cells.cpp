#include "unit_cells.hpp"

#include <cmath>

#include "granpipe/errors.hpp"

namespace granpipe::lattice {

const std::vector<std::string>& lattice_names() {
  static const std::vector<std::string> names{"square", "triangular", "sc", "bcc", "fcc", "hcp"};
  return names;
}

UnitCell unit_cell(const std::string& name) {
  const double s3 = std::sqrt(3.0);
  UnitCell c;
  if (name == "square") {
    c.dim = 2;
    c.size = {1, 1, 0};
    c.basis = {{0, 0, 0}};
  } else if (name == "triangular") {
    // Two horizontal close-packed rows, the second shifted by half a spacing.
    c.dim = 2;
    c.size = {1, s3, 0};
    c.basis = {{0, 0, 0}, {0.5, 0.5 * s3, 0}};
  } else if (name == "sc") {
    c.size = {1, 1, 1};
    c.basis = {{0, 0, 0}};
  } else if (name == "bcc") {
    // Nearest neighbours along the body diagonal: a sqrt(3)/2 = 1.
    const double a = 2.0 / s3;
    c.size = {a, a, a};
    c.basis = {{0, 0, 0}, {a / 2, a / 2, a / 2}};
  } else if (name == "fcc") {
    // Nearest neighbours along the face diagonal: a / sqrt(2) = 1.
    const double a = std::sqrt(2.0);
    c.size = {a, a, a};
    c.basis = {{0, 0, 0}, {a / 2, a / 2, 0}, {a / 2, 0, a / 2}, {0, a / 2, a / 2}};
  } else if (name == "hcp") {
    // Orthohexagonal cell: two triangular layers A (z = 0) and B (z = c/2), B over the
    // centroids of A's triangles; c = sqrt(8/3) makes inter-layer neighbours touch.
    const double cz = std::sqrt(8.0 / 3.0);
    c.size = {1, s3, cz};
    c.basis = {{0, 0, 0},
               {0.5, 0.5 * s3, 0},
               {0.5, s3 / 6, 0.5 * cz},
               {0, s3 / 6 + 0.5 * s3, 0.5 * cz}};
  } else {
    throw InternalError("lattice: unknown lattice \"" + name + "\"");
  }
  return c;
}

}  // namespace granpipe::lattice
