#pragma once
// The force statistics of subsets of the force-network contacts named by an integer
// contact column of pass numbers (the mst analyzer's mst_pass: the first pass of the
// multipass MST that captured the contact, 0 for none): for k = 1 .. the largest pass,
// the contacts with 1 <= pass <= k, as in the paper's Figs. 14–16. Forces are scaled by
// the FULL network's <F_n>, and binned on the full network's PDF bins, so that each
// subset's PDF is compared with the full one bin by bin.
//
// Each subset's PDF is fitted by Eq. (13) twice:
//  - "free": a, b, alpha, beta free and gamma = 0. Eq. (13) depends on a and gamma only
//    through a exp(beta gamma), so the five cannot all be free; gamma = 0 loses nothing
//    (any other gamma is the same curve with a exp(-beta gamma) for a);
//  - "shift": a, b, beta fixed to the full network's Eq. (11) fit, alpha and gamma free
//    (the main panels of the paper's Fig. 15).
#include <string>
#include <vector>

#include "force_contacts.hpp"
#include "force_correlation.hpp"
#include "force_pdf.hpp"
#include "pdf_fit.hpp"
#include "settings.hpp"

namespace granpipe::force_network {

struct PassSubset {
  long pass = 0;      // k
  long contacts = 0;  // force-network contacts with 1 <= pass <= k
  ForcePdf pdf;
  ForceCorrelation correlation;
  PdfFit free_fit, shift_fit;
};

// The largest pass accepted; a column holding more is refused (it is not a pass number).
inline constexpr long kMaxPasses = 1000;

// The frame's pass column named by settings.by_pass. Throws InputError after `where`
// when the frame has no contacts or the contacts lack it.
const IndexArray& pass_column(const Frame& frame, const Settings& settings,
                              const std::string& where);

// Throws InputError after `where` when the pass column is missing, or holds a pass beyond
// kMaxPasses.
std::vector<PassSubset> pass_subsets(const Frame& frame, const ForceContacts& forces,
                                     const std::vector<double>& pdf_edges, const PdfFit& full,
                                     const Settings& settings, const std::string& where);

}  // namespace granpipe::force_network
