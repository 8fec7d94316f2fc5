#pragma once
// Eq. (7) of the 3D tapping paper: the vertical packing-fraction profile as a Fermi-like
// step, phi(z) = (phi0 - alpha z) / (1 + exp(beta (z - zstar))), z in mean radii: a bulk
// value phi0 with a gradient alpha, falling to 0 over ~1/beta about the surface zstar.
#include <vector>

#include "granpipe/curve_fit.hpp"

namespace granpipe::stereology {

enum FermiParameter { kPhi0 = 0, kAlpha, kBeta, kZstar, kFermiParameters };
inline constexpr const char* kFermiNames[] = {"phi0", "alpha", "beta", "zstar"};
inline constexpr const char* kFermiFormula =
    "phi(z) = (phi0 - alpha z) / (1 + exp(beta (z - zstar))), z = height / R";

CurveModel fermi_model();

// Fits Eq. (7) to the profile phi[k] at heights z[k] (mean radii) with z >= from. Starts
// from the median of the profile between `from` and the surface as phi0, no gradient,
// beta = 1 and zstar where the profile first falls below half that median.
CurveFit fit_fermi_profile(const std::vector<double>& z, const std::vector<double>& phi,
                           double from);

}  // namespace granpipe::stereology
