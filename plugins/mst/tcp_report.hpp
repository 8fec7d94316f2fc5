#pragma once
// One frame through the multipass MST: the candidate graph, the passes, and after each
// pass the trees of contacting particles (TCPs: the contacting edges selected so far)
// against the contact network, as the paper's Table II counts them.
#include <string>
#include <vector>

#include "candidate_edges.hpp"
#include "components.hpp"
#include "contact_pairs.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/frame_cache.hpp"

namespace granpipe::mst {

struct MstOptions {
  Candidates candidates = Candidates::Cutoff;
  double cutoff = 1.25;
  double elongation = 1.2;
  int passes = 5;
  ContactRule contacts{};
};

struct PassRow {
  int pass = 0;
  TreeCounts tcp;             // of the contacting edges selected up to this pass
  std::int64_t selected = 0;  // contacting edges selected up to this pass
};

struct TcpReport {
  std::vector<PassRow> passes;
  TreeCounts network;        // of all contact pairs
  std::int64_t contacts = 0;  // pairs in contact
  std::size_t candidate_edges = 0;
  // True when every contacting edge's selection is provably that of the MST over all
  // pairs (docs/mst.md): (elongation) x (longest contact) below the shortest pair the
  // candidate graph may miss.
  bool exact = false;
  double longest_contact = 0.0, complete_below = 0.0;
  // Per contact pair (ContactPairs::pairs): the first pass that selected it, 0 if none.
  std::vector<int> first_pass;
  ContactPairs pairs;
  IndexArray tcp;  // per particle after the last pass, -1 if in none

  double recovered(const PassRow& row) const {
    return contacts > 0 ? static_cast<double>(row.selected) / static_cast<double>(contacts) : 0.0;
  }
};

TcpReport tcp_report(const Frame& frame, FrameCache& cache, const MstOptions& options,
                     const std::string& where);

}  // namespace granpipe::mst
