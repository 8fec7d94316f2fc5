#pragma once
// The `force_network` analyzer: force networks, the strong sub-network, the force PDF with
// the fit of Eq. (11) and the force-force correlation F(r) of Eq. (12) of the BNP paper
// (Sec. III.B), per frame (streamed) and in full for the paper's frame; with `by_pass`,
// the same statistics of the contacts captured by the passes of a multipass MST (Sec.
// III.C). docs/force_network.md says what each output means.
#include <string>

#include "frame_analysis.hpp"
#include "granpipe/loaded_pair_contacts.hpp"
#include "granpipe/log.hpp"
#include "granpipe/plugin.hpp"
#include "settings.hpp"

namespace granpipe::force_network {

Schema schema();

class ForceNetworkAnalyzer : public Analyzer {
 public:
  explicit ForceNetworkAnalyzer(const PluginContext& ctx);
  FrameContent needs() const override;
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;
  std::vector<Property> publishes() const override;
  void publish(PropertyTable& columns) override;

  static Property network_property();
  static Property strong_property();

 private:
  // Warns, once per run, that a frame without force samples has undefined statistics.
  void warn_undefined(const FrameAnalysis& a, const std::string& where);

  Log& log_;
  Settings settings_;
  long frames_ = 0;
  FirstFrameWarning undefined_;
  StreamedTable per_frame_;
  MostLoadedFrame chosen_;
  PaperFrame paper_;    // of the chosen frame
  IndexArray network_;  // of the last frame consumed, for publish()
  IntArray strong_;
};

}  // namespace granpipe::force_network
