#pragma once
// What the stereology analyzer measures in one frame (3D tapping paper, Secs. II and
// IV.A), every fraction an exact integral of cut areas (granpipe/cut_profile.hpp):
//  - the global fractions phi_b and phi_c (granpipe/stereology.hpp);
//  - the vertical profile: bins of `step` mean radii from the bottom to the top of the
//    highest particle, over the whole cross-section;
//  - the transversal profile: bins across x (the first lateral axis) tiling the width,
//    over heights 0..H (phi_c's zone);
//  - the lateral fraction (within lateral_band radii of either x side) and the central
//    one (the rest), over the same heights;
//  - the fit of Eq. (7) to the vertical profile from fit_from radii up.
#include <string>
#include <vector>

#include "fermi_profile.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/stereology.hpp"

namespace granpipe::stereology {

// The narrowest zone measured, in mean radii: lateral_band's least value, and the least
// width of the central zone (a narrower one leaves phi_central undefined).
constexpr double kNarrowestZone = 1e-3;

struct ProfileSettings {
  StereologySettings global;
  double step = 0.1;  // R
  // Where these sit in the pipeline ("analyzers[1].params"), so that messages name them.
  std::string params = "stereology";
  double lateral_band = 7.0;  // R
  double fit_from = 5.0;      // R
};

struct ProfileMeasurement {
  GlobalFractions global;
  double transversal_step = 0.0;  // R: the width over a whole number of bins
  std::vector<double> vertical, transversal;
  double lateral = 0.0, central = 0.0;  // NaN: no central zone (narrower than kNarrowestZone)
  CurveFit fit;                         // Eq. (7)
};

// Throws InputError for a frame that is not a box or has no particles.
ProfileMeasurement measure_profiles(const Frame& frame, const ProfileSettings& settings);

}  // namespace granpipe::stereology
