// A plugin library that claims another ABI version: the loader must refuse it
// without calling its registration function.
#include <cstdlib>

#include "granpipe/plugin.hpp"

static void register_nothing(granpipe::Registry&) { std::abort(); }

extern "C" __attribute__((visibility("default"))) const granpipe_plugin_entry granpipe_plugin = {
    GRANPIPE_ABI_VERSION + 1, granpipe::kLayoutFingerprint, "99.0.0", &register_nothing};
