#include "granpipe/plugin.hpp"
#include "tap_source.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_source<granpipe::disks2d_tap::TapSource>(
      "disks2d_tap",
      "tapped hard disks in a box: Manna-Khakhar deposition, dilation + Monte Carlo taps, "
      "support labels",
      granpipe::disks2d_tap::schema());
}
