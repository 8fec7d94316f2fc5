#include "compaction_analyzer.hpp"
#include "granpipe/plugin.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::compaction::CompactionAnalyzer>(
      "compaction",
      "compaction dynamics of a tapping run: <Z>, phi_b, <phi^c> per tap, the fits of Eqs. "
      "(3) and (4), steady state and power spectrum, ageing squared differences (Eq. 5)",
      granpipe::compaction::schema());
}
