#pragma once
// The inverse-logarithmic laws of the 3D tapping paper, in the form the core fitter takes:
//   Eq. (3)  X(t)   = X_inf - dX_inf / (1 + B ln(1 + t/tau))             (phi_b, <phi^c>)
//   Eq. (4)  <Z>(t) = Z_inf (1 + B L) / (Z_inf/Z_0 + B L), L = ln(1 + t/tau)
//   Eq. (6)  A(t)   = A_inf (1 - 1 / (1 + B ln(1 + t/tau)))
// Each law's last parameter is ln(tau) inside the fit, so that no step of the minimiser
// makes tau negative (ln(1 + t/tau) undefined); law_fit.hpp reports tau itself.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "granpipe/curve_fit.hpp"

namespace granpipe::compaction {

// The data's two ends, from which a law's start values are chosen.
struct SeriesEnds {
  double y_first = 0.0;               // at the earliest t
  double t_last = 0.0, y_last = 0.0;  // means over the last tenth of the points
};

struct Law {
  std::string formula;
  std::vector<std::string> names;  // as reported, tau last
  CurveModel model;
  // Start values (tau as ln tau) of a curve through both ends with tau = 1 tap, B = 1.
  Eigen::VectorXd (*start)(const SeriesEnds&);
};

const Law& eq3_law();
const Law& eq4_law();
const Law& eq6_law();

}  // namespace granpipe::compaction
