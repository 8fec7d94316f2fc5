#pragma once
// One frame through the multipass MST: the candidate graph, the passes, and after each
// pass the trees of contacting particles (TCPs: the contacting edges selected so far)
// against the contact network, as the paper's Table II counts them.
#include <cmath>
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
  double cutoff = 0.0;  // 0: the smallest that proves every contact's selection, capped
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
  TreeCounts network;         // of all contact pairs
  std::int64_t contacts = 0;  // pairs in contact
  double cutoff = 0.0;        // candidates "cutoff": the factor used
  // Every pair shorter than this is a candidate; a contact whose weight stays below it in
  // every pass is selected exactly as by the MST of all pairs (docs/mst.md).
  double complete_below = 0.0;
  std::int64_t unproven = 0;  // contacts for which that is not shown
  // Per contact pair (ContactPairs::pairs): the first pass that selected it, 0 if none.
  std::vector<int> first_pass;
  ContactPairs pairs;
  IndexArray tcp;  // per particle after the last pass, -1 if in none

  // The share of contacts selected: NaN (undefined, not 0) for a frame without contacts.
  double recovered(const PassRow& row) const {
    return contacts > 0 ? static_cast<double>(row.selected) / static_cast<double>(contacts)
                        : std::nan("");
  }
};

TcpReport tcp_report(const Frame& frame, FrameCache& cache, const MstOptions& options,
                     const std::string& where);

}  // namespace granpipe::mst
