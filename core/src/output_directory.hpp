#pragma once
#include <filesystem>
#include <string>

#include "granpipe/atomic_file.hpp"

namespace granpipe {

// Creates the run's output directory. An existing non-empty directory is an InputError
// unless `overwrite`, and even then only a directory granpipe wrote (it has a
// pipeline.json) is cleared: nothing else a user has is ever deleted.
void prepare_output_directory(const std::filesystem::path& dir, bool overwrite);

}  // namespace granpipe
