#pragma once
// A fingerprint of the memory layout of the types a plugin and the core pass to each
// other. A plugin built against other public headers (a field added, a type changed,
// another standard library ABI or packing) would read the core's objects at the wrong
// offsets and fail far from the cause (a std::bad_alloc, a wrong result); comparing the
// fingerprint compiled into the plugin with the core's refuses it at load time, even when
// nobody remembered to bump GRANPIPE_ABI_VERSION.
#include <cstdint>
#include <initializer_list>

#include "granpipe/container.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/frame_cache.hpp"
#include "granpipe/log.hpp"
#include "granpipe/output_files.hpp"
#include "granpipe/params.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/progress.hpp"
#include "granpipe/property.hpp"
#include "granpipe/property_table.hpp"
#include "granpipe/random.hpp"
#include "granpipe/results.hpp"

namespace granpipe {

namespace abi_detail {
// FNV-1a over the sizes and alignments, in a fixed order.
constexpr std::uint64_t fnv1a(std::initializer_list<std::uint64_t> values) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::uint64_t v : values) {
    for (int byte = 0; byte < 8; ++byte) {
      h ^= (v >> (8 * byte)) & 0xffu;
      h *= 1099511628211ull;
    }
  }
  return h;
}
}  // namespace abi_detail

// Sizes and alignments of every public type that crosses the plugin boundary.
#define GRANPIPE_LAYOUT_OF(T) sizeof(T), alignof(T)
inline constexpr std::uint64_t kLayoutFingerprint = abi_detail::fnv1a({
    GRANPIPE_LAYOUT_OF(Property),      GRANPIPE_LAYOUT_OF(Column),
    GRANPIPE_LAYOUT_OF(PropertyTable), GRANPIPE_LAYOUT_OF(Frame),
    GRANPIPE_LAYOUT_OF(Container),     GRANPIPE_LAYOUT_OF(Coordinates),
    GRANPIPE_LAYOUT_OF(FrameCache),    GRANPIPE_LAYOUT_OF(Log),
    GRANPIPE_LAYOUT_OF(ParamSpec),     GRANPIPE_LAYOUT_OF(Schema),
    GRANPIPE_LAYOUT_OF(Params),        GRANPIPE_LAYOUT_OF(SpeciesTable),
    GRANPIPE_LAYOUT_OF(PairTable),     GRANPIPE_LAYOUT_OF(PairMatrix),
    GRANPIPE_LAYOUT_OF(Progress),      GRANPIPE_LAYOUT_OF(RandomStream),
    GRANPIPE_LAYOUT_OF(Seeds),         GRANPIPE_LAYOUT_OF(Scalar),
    GRANPIPE_LAYOUT_OF(Table),         GRANPIPE_LAYOUT_OF(Histogram),
    GRANPIPE_LAYOUT_OF(Fit),           GRANPIPE_LAYOUT_OF(Plot),
    GRANPIPE_LAYOUT_OF(Results),       GRANPIPE_LAYOUT_OF(RunningMean),
    GRANPIPE_LAYOUT_OF(StreamedTable), GRANPIPE_LAYOUT_OF(FrameContent),
    GRANPIPE_LAYOUT_OF(PluginContext), GRANPIPE_LAYOUT_OF(PluginInfo),
    GRANPIPE_LAYOUT_OF(Registry),      GRANPIPE_LAYOUT_OF(OutputFiles),
});
#undef GRANPIPE_LAYOUT_OF

}  // namespace granpipe
