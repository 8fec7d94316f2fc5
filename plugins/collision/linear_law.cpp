#include "linear_law.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "granpipe/errors.hpp"

namespace granpipe::collision {

LinearPrediction predict_linear(double kn, double gamma_n, double m_eff, const std::string& where) {
  const double omega2 = kn / m_eff - 0.25 * gamma_n * gamma_n;
  if (!(omega2 > 0.0)) {
    std::ostringstream s;
    s << where
      << ": expected an underdamped pair (k_n/m_eff > gamma_n^2/4), got k_n/m_eff = " << kn / m_eff
      << " and gamma_n^2/4 = " << 0.25 * gamma_n * gamma_n;
    throw InputError(s.str());
  }
  const double t_c = std::numbers::pi / std::sqrt(omega2);
  return {t_c, std::exp(-0.5 * gamma_n * t_c)};
}

}  // namespace granpipe::collision
