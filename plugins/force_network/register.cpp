#include "force_network_analyzer.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::force_network::ForceNetworkAnalyzer>(
      "force_network",
      "force networks, strong sub-network, force PDF with the Eq. (11) fit and F(r) (BNP paper "
      "Sec. III.B); with by_pass, the same per MST pass with Eq. (13) fits",
      granpipe::force_network::schema());
}
