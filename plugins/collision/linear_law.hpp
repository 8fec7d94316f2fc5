#pragma once
// What the linear spring-dashpot law predicts for a collision (the seed paper's Eqs. 9-10, in
// the `dem` source's convention F_n = k_n delta - gamma_n m_eff v_n): the overlap obeys
// delta'' + gamma_n delta' + (k_n/m_eff) delta = 0, which lasts
// t_c = pi / sqrt(k_n/m_eff - gamma_n^2/4) and returns the approach speed times
// e = exp(-gamma_n t_c / 2).
#include <string>

namespace granpipe::collision {

struct LinearPrediction {
  double contact_time = 0.0;
  double restitution = 0.0;
};

// Throws InputError starting with `where` for an overdamped pair (no rebound to measure).
LinearPrediction predict_linear(double kn, double gamma_n, double m_eff, const std::string& where);

}  // namespace granpipe::collision
