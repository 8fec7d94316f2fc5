#pragma once
// The steady state (SS) of a quantity X over the late frames of a run: X_SS its mean, and
// the paper's sigma_X = sqrt(<(X - X_SS)^2>), the spread of the fluctuations (Fig. 3).
#include <vector>

namespace granpipe::compaction {

struct SteadyState {
  double mean = 0.0;        // X_SS; NaN without finite values
  double mean_error = 0.0;  // sigma_X / sqrt(n - 1): as if the frames were independent
  double sigma = 0.0;       // sigma_X, the population spread (the paper's definition)
  long frames = 0;          // finite values used
};

// Non-finite values are left out.
SteadyState steady_state(const std::vector<double>& values);

}  // namespace granpipe::compaction
