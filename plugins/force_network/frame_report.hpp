#pragma once
// The paper's frame as results: the force PDF with the Eq. (11) fit, F(r), and the
// subsets by pass with their Eq. (13) fits.
#include "frame_analysis.hpp"
#include "granpipe/results.hpp"

namespace granpipe::force_network {

// Nothing when no frame was seen. Fits without values are reported by their status only.
void report_paper_frame(const PaperFrame& frame, Results& results);

}  // namespace granpipe::force_network
