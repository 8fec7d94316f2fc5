#include "granpipe/plugin.hpp"
#include "tap_source.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_source<granpipe::spheres3d_tap::TapSource>(
      "spheres3d_tap",
      "tapped hard spheres in a box: sequential deposition to three supports, dilation + "
      "gravity-biased Monte Carlo redeposition",
      granpipe::spheres3d_tap::schema());
}
