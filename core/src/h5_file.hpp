#pragma once
// Creating an HDF5 file with the operating system's reason when it cannot be made: on a
// full disk HDF5 fails only with "unable to create file", the reason sits deeper in its
// error stack.
#include <hdf5.h>

#include <string>

#include "h5_object.hpp"

namespace granpipe::h5 {

// The reason the operating system gave for the last failed HDF5 call of this thread ("No
// space left on device"), from HDF5's error stack, or "" when it quotes none.
std::string system_reason();

// Creates `name` with `flags` (H5F_ACC_EXCL, H5F_ACC_TRUNC) and file access list `access`,
// or throws Error("cannot create the file (<reason>)").
Object create_file(const std::string& name, unsigned flags, hid_t access);

}  // namespace granpipe::h5
