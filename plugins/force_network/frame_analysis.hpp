#pragma once
// Everything force_network measures on one frame, and the frame's row of the per-frame
// table; the paper's frame (the one kept for the full tables) adds F(r) and the subsets.
#include <string>
#include <vector>

#include "force_contacts.hpp"
#include "force_correlation.hpp"
#include "force_pdf.hpp"
#include "networks.hpp"
#include "pass_subsets.hpp"
#include "pdf_fit.hpp"
#include "settings.hpp"
#include "strong_network.hpp"

namespace granpipe::force_network {

struct FrameAnalysis {
  ForceContacts forces;
  Networks networks;
  StrongNetwork strong;
  std::vector<double> scaled;  // f = |F_n| / <F_n> of each sample
  ForcePdf pdf;                // of f over the samples
  PdfFit fit;                  // Eq. (11)
};

// Throws InputError after `where` for a frame without contacts or normal_force.
FrameAnalysis analyse_frame(const Frame& frame, const Settings& settings, const std::string& where);

// The frame whose full tables force_network reports: the one with the most particle–particle
// contacts with |F_n| > 0, the earliest of equals (granpipe::MostLoadedFrame; the mst
// analyzer picks the same).
struct PaperFrame {
  long index = -1;  // none yet
  double time = 0.0;
  long loaded = -1;
  ForcePdf pdf;
  PdfFit fit;
  ForceCorrelation correlation;
  std::vector<PassSubset> passes;  // empty unless by_pass is set
};

PaperFrame paper_frame(const Frame& frame, const FrameAnalysis& a, long index,
                       const Settings& settings, const std::string& where);

// The per-frame table: its columns, and one frame's row.
std::vector<std::string> per_frame_columns();
std::vector<double> per_frame_row(long index, double time, Eigen::Index particles,
                                  const FrameAnalysis& a);

}  // namespace granpipe::force_network
