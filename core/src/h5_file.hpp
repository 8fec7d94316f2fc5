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
Object create_file(const std::string& name, unsigned flags, hid_t access,
                   hid_t creation = H5P_DEFAULT);

// A file access list asking for the latest file format, which SWMR needs.
Object latest_format_access();

// Creates `name` (never replacing a file) for SWMR writing: the latest file format, which
// SWMR needs, and paged file space, so that no metadata block straddles a 4 KiB page. A
// killed process's last write is cut at a page boundary (the kernel checks for a fatal
// signal between pages); a block within one page is then written whole or not at all, and
// a reader never meets a half-written object header (tests/core/test_frame_store.cpp).
Object create_swmr_file(const std::string& name);

}  // namespace granpipe::h5
