#pragma once
// The global packing fractions of the 3D tapping paper (Sec. II), from horizontal cuts
// integrated exactly (cut_profile.hpp) over the container's whole cross-section:
//  - phi_b, the fraction between the bottom and bulk_top mean radii above it;
//  - phi_c, the fraction from the bottom up to the height below which `fraction` of the
//    centres lie, its layer between the bottom and perturbed_top radii multiplied by
//    perturbed_factor (the perturbed-zone model: 16/11 for spheres on a plane), i.e.
//    phi_c = [factor * Phi(0, R1) R1 + Phi(R1, H) (H - R1)] / H.
//    The paper gives the factor for spheres only: a factor of 0 (the default) stands for
//    16/11 in 3D and is refused for disks, which need one given.
// Heights are above the container's bottom, in mean particle radii R.
#include <string>

#include "granpipe/frame.hpp"
#include "granpipe/params.hpp"

namespace granpipe {

struct StereologySettings {
  double bulk_top = 4.0;          // R
  double perturbed_top = 1.0;     // R
  double perturbed_factor = 0.0;  // the bottom layer's correction; 0: 16/11 for spheres
  double fraction = 0.9;          // of the centres, below the top of phi_c's zone
  // How messages name perturbed_factor: its path in the pipeline (analyzers[0].params...).
  std::string factor_name = "perturbed_factor";
};

struct GlobalFractions {
  double radius = 0.0;  // the mean radius R, the unit of the settings
  // NaN when the frame has no particles, or when bulk_top reaches above the highest
  // particle top (the slab would be partly empty space above the bed: no bulk)
  double phi_b = 0.0;
  double phi_c = 0.0;     // NaN when the zone is not above the perturbed layer
  double height_c = 0.0;  // H, the top of phi_c's zone above the bottom (length)
  double top = 0.0;       // the highest particle top above the bottom (length)
};

// The four settings as parameters of an analyzer's schema (bulk_top, perturbed_top,
// perturbed_factor, fraction), and read back from its validated parameters, the factor's
// refusals naming it `factor_name` (ctx.param("perturbed_factor")).
void declare_stereology_settings(Schema& schema);
StereologySettings stereology_settings(const Params& params, std::string factor_name);

// Throws InputError for a container that is not a box (the cuts need a rectangular
// cross-section) or is periodic along the vertical (no bottom to measure heights from),
// and for disks with perturbed_factor 0 (no published factor to stand for).
GlobalFractions global_fractions(const Frame& frame, const StereologySettings& settings);

// Why phi_b or phi_c of a frame with particles is NaN, in words for a warning ("" when
// both are defined): "phi_b is undefined (NaN): bulk_top, 1000 R, reaches above the
// highest particle top, 11.9 R".
std::string undefined_fractions(const GlobalFractions& fractions,
                                const StereologySettings& settings);

}  // namespace granpipe
