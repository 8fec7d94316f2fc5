#include "percus_yevick.hpp"

#include <cmath>

namespace granpipe::pores {

double p0_percus_yevick(double phi, double sigma) {
  const double hole = 1.0 - phi;
  const double linear = 3.0 * phi / hole;
  const double quadratic = 3.0 * phi / hole + 4.5 * phi * phi / (hole * hole);
  const double cubic = phi * (1.0 + phi + phi * phi) / (hole * hole * hole);
  const double work = sigma * (linear + sigma * (quadratic + sigma * cubic));
  return hole * std::exp(-work);
}

}  // namespace granpipe::pores
