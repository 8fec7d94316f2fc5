#include "granpipe/plugin.hpp"
#include "stereology_analyzer.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_analyzer<granpipe::stereology::StereologyAnalyzer>(
      "stereology",
      "packing fractions from exact cuts (the 3D tapping paper): phi_b, phi_c with the "
      "perturbed-zone correction, vertical and transversal profiles, lateral and central "
      "fractions against the first frame, the Eq. (7) fit",
      granpipe::stereology::schema());
}
