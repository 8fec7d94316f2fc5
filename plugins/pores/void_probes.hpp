#pragma once
// Random probes of the void: points uniform in a box, and each one's distance to the
// surface of the nearest sphere, from which P0(sigma), the probability that a probe
// sphere of radius sigma R overlaps no sphere, follows.
#include <optional>
#include <string>
#include <vector>

#include "granpipe/frame.hpp"
#include "granpipe/random.hpp"
#include "granpipe/region.hpp"
#include "pore_region.hpp"

namespace granpipe::pores {

// The box the probes fill: `region` (the pores' inner region, nothing for all) cut to the
// container's box. Throws InputError after `where` for a container that is no box.
Region probe_region(const Frame& frame, const std::optional<PoreRegion>& region,
                    const std::string& where);

// For `probes` points uniform in `box`: the distance from each to the nearest sphere
// surface (negative inside a sphere); +infinity where no surface is within `reach`, which
// is not looked beyond. Periodic sides by minimum image (a period must be at least twice
// reach plus the largest radius: InputError after `where` otherwise).
std::vector<double> probe_gaps(const Frame& frame, const Region& box, long probes, double reach,
                               RandomStream& stream, const std::string& where);

}  // namespace granpipe::pores
