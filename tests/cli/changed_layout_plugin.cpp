// A plugin compiled against the public headers with another layout of their types (here
// by packing every struct, as a plugin built with other compiler flags or other headers
// would be): the loader must refuse it by its layout fingerprint without calling into it.
#include <cstdlib>

#pragma pack(push, 1)
#include "granpipe/plugin.hpp"
#pragma pack(pop)

static void register_nothing(granpipe::Registry&) { std::abort(); }

extern "C" __attribute__((visibility("default"))) const granpipe_plugin_entry granpipe_plugin = {
    GRANPIPE_ABI_VERSION, granpipe::kLayoutFingerprint, GRANPIPE_VERSION, &register_nothing};

static_assert(granpipe::kLayoutFingerprint != 0);
