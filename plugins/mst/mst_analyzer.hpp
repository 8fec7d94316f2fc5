#pragma once
// The `mst` analyzer: the multipass minimum spanning tree of the paper's Sec. III.C on
// every frame, with Table II (TCPs against the contact network, per pass) streamed per
// frame and written for the frame with the most loaded contacts. Publishes, per contact,
// the first pass that selected it (mst_pass) and, per particle, its TCP after the last pass.
#include <vector>

#include "granpipe/loaded_pair_contacts.hpp"
#include "granpipe/log.hpp"
#include "granpipe/plugin.hpp"
#include "tcp_report.hpp"

namespace granpipe::mst {

Schema schema();

class MstAnalyzer : public Analyzer {
 public:
  explicit MstAnalyzer(const PluginContext& ctx);
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;
  std::vector<Property> publishes() const override;
  void publish(PropertyTable& columns) override;

 private:
  void keep_table_ii(const Frame& frame, const TcpReport& report);
  void warn_idle_contact_rule() const;

  Log& log_;
  MstOptions options_;
  long frames_ = 0;
  long frames_with_table_ = 0;  // frames whose contact table gave the contacts
  bool warned_inexact_ = false;
  FirstFrameWarning no_contacts_;
  FirstFrameWarning coarse_;  // contacts by distance from positions rounded coarser than that
  StreamedTable per_frame_;
  // Table II of the frame with the most loaded pair contacts (the first of equals).
  MostLoadedFrame chosen_;
  Table table_ii_;
  double chosen_time_ = 0.0;
  // Of the last frame, for publish().
  IndexArray mst_pass_, tcp_;
};

}  // namespace granpipe::mst
