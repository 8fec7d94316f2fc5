#include "granpipe/plugin.hpp"
#include "mst_analyzer.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::mst::MstAnalyzer>(
      "mst",
      "multipass minimum spanning tree: trees of contacting particles against the contact "
      "network per pass (Table II), the pass that selected each contact",
      granpipe::mst::schema());
}
