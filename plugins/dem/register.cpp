// The dem plugin. Its engine (dem_lib) is ready; the `dem` source that runs it from a
// pipeline is registered here once it exists (issue 12).
#include "granpipe/plugin.hpp"

GRANPIPE_PLUGIN(registry) { static_cast<void>(registry); }
