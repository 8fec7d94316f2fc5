#pragma once
// A picture of a packing with its arches (the paper's Fig. 4) as SVG: the box walls,
// every disk as a circle (disks in arches shaded), every mutual link as a line joining
// the centres of the two disks.
#include <filesystem>
#include <string>
#include <vector>

#include "mutual_stability.hpp"

namespace granpipe::arches {

// Writes atomically (temporary file, then rename), the run's `provenance` (pipeline,
// version, commit, seed) as the picture's description. Throws InputError when the file
// cannot be written.
void write_arches_svg(const std::filesystem::path& path, const Frame& frame,
                      const std::vector<Arch>& arches, const std::string& title,
                      const std::string& provenance);

}  // namespace granpipe::arches
