#pragma once
// The force_network analyzer's parameters, as its parts use them.
#include <string>

#include "force_contacts.hpp"

namespace granpipe::force_network {

struct Settings {
  ForceSettings force;
  double bin_width = 0.2;  // of the PDF, in f
  double f_max = 0.0;      // <= 0: the largest f of the frame
  long min_fit_samples = 100;
  double r_max = 10.0;  // length
  int r_bins = 50;
  std::string by_pass;  // contact column of pass numbers; empty: no subsets
};

}  // namespace granpipe::force_network
