#include "void_probes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "granpipe/cell_list.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/stop_request.hpp"

namespace granpipe::pores {

Region probe_region(const Frame& frame, const std::optional<PoreRegion>& region,
                    const std::string& where) {
  const Container& c = frame.container;
  if (c.shape != ContainerShape::Box) {
    throw InputError(where + ": P0 probes expected a box container, got a " + to_string(c.shape) +
                     " (set probes 0, sigma_step and sigma_max at their defaults)");
  }
  Region box;
  box.dim = 3;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = region ? std::max(region->box.lo[a], c.lo[a]) : c.lo[a];
    box.hi[a] = region ? std::min(region->box.hi[a], c.hi[a]) : c.hi[a];
  }
  return box;
}

std::vector<double> probe_gaps(const Frame& frame, const Region& box, long probes, double reach,
                               RandomStream& stream, const std::string& where) {
  const double cutoff = reach + frame.radius().maxCoeff();
  const CellList cells(frame.position(), frame.container, 3, cutoff, where);
  std::vector<double> gaps;
  gaps.reserve(static_cast<std::size_t>(probes));
  for (long k = 0; k < probes; ++k) {
    // 10^8 probes took a minute to stop after SIGTERM.
    if (k % 65536 == 0) throw_if_stop_requested();
    double x[3];
    for (int a = 0; a < 3; ++a) x[a] = stream.uniform(box.lo[a], box.hi[a]);
    double gap = std::numeric_limits<double>::infinity();
    cells.for_each_near(x, cutoff, [&](int j, const double*, double r2) {
      gap = std::min(gap, std::sqrt(r2) - frame.radius()[j]);
    });
    gaps.push_back(gap);
  }
  return gaps;
}

}  // namespace granpipe::pores
