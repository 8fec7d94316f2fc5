#include "granpipe/mean_profile.hpp"

namespace granpipe {

void MeanProfile::add(const std::vector<double>& profile) {
  if (profile.size() > bins_.size()) {
    const std::size_t old = bins_.size();
    bins_.resize(profile.size());
    for (std::size_t k = old; k < bins_.size(); ++k) bins_[k].add(0.0, frames_);
  }
  for (std::size_t k = 0; k < bins_.size(); ++k) {
    bins_[k].add(k < profile.size() ? profile[k] : 0.0);
  }
  ++frames_;
}

}  // namespace granpipe
