#include "granpipe/plugin.hpp"
#include "h5md_source.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_source<granpipe::h5md::H5mdSource>(
      "h5md", "frames read back from an H5MD file (granpipe's frames.h5 or another tool's)",
      granpipe::h5md::schema());
}
