#include "unit_cells.hpp"

#include <cmath>

#include "granpipe/errors.hpp"

namespace granpipe::lattice {

UnitCell unit_cell(Lattice lattice) {
  const double s3 = std::sqrt(3.0);
  switch (lattice) {
    case Lattice::Square:
      return {2, {1, 1, 0}, {{0, 0, 0}}};
    case Lattice::Triangular:
      // Two horizontal close-packed rows, the second shifted by half a spacing.
      return {2, {1, s3, 0}, {{0, 0, 0}, {0.5, 0.5 * s3, 0}}};
    case Lattice::Sc:
      return {3, {1, 1, 1}, {{0, 0, 0}}};
    case Lattice::Bcc: {
      // Nearest neighbours along the body diagonal: a sqrt(3)/2 = 1.
      const double a = 2.0 / s3;
      return {3, {a, a, a}, {{0, 0, 0}, {a / 2, a / 2, a / 2}}};
    }
    case Lattice::Fcc: {
      // Nearest neighbours along the face diagonal: a / sqrt(2) = 1.
      const double a = std::sqrt(2.0);
      return {3, {a, a, a}, {{0, 0, 0}, {a / 2, a / 2, 0}, {a / 2, 0, a / 2}, {0, a / 2, a / 2}}};
    }
    case Lattice::Hcp: {
      // Orthohexagonal cell: two triangular layers A (z = 0) and B (z = c/2), B over the
      // centroids of A's triangles; c = sqrt(8/3) makes inter-layer neighbours touch.
      const double cz = std::sqrt(8.0 / 3.0);
      return {3,
              {1, s3, cz},
              {{0, 0, 0},
               {0.5, 0.5 * s3, 0},
               {0.5, s3 / 6, 0.5 * cz},
               {0, s3 / 6 + 0.5 * s3, 0.5 * cz}}};
    }
  }
  throw InternalError("lattice: an unnamed lattice");
}

}  // namespace granpipe::lattice
