#include "h5_file.hpp"

#include <cstdlib>
#include <cstring>

namespace granpipe::h5 {

namespace {

constexpr hsize_t kPage = 4096;  // the kernel's page: the unit a killed write is cut at

// Keeps the first errno that a message of HDF5's error stack quotes
// ("... errno = 28, error message = 'No space left on device' ...").
herr_t find_errno(unsigned, const H5E_error2_t* error, void* found) {
  int& code = *static_cast<int*>(found);
  const char* at = error->desc ? std::strstr(error->desc, "errno = ") : nullptr;
  if (code == 0 && at) code = std::atoi(at + std::strlen("errno = "));
  return 0;
}

}  // namespace

std::string system_reason() {
  int code = 0;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, find_errno, &code);
  return code > 0 ? std::strerror(code) : "";
}

Object create_file(const std::string& name, unsigned flags, hid_t access, hid_t creation) {
  const hid_t id = H5Fcreate(name.c_str(), flags, creation, access);
  if (id >= 0) return Object(id);
  const std::string reason = system_reason();
  throw Error(
      "cannot create the file (" +
      (reason.empty() ? "does its directory exist, is it writable, is the disk full?" : reason) +
      ")");
}

Object latest_format_access() {
  Object access = owned(H5Pcreate(H5P_FILE_ACCESS), "cannot make the file access list");
  check(H5Pset_libver_bounds(access.id(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST),
        "cannot ask for the latest file format");
  return access;
}

Object create_swmr_file(const std::string& name) {
  const Object access = latest_format_access();
  const Object creation = owned(H5Pcreate(H5P_FILE_CREATE), "cannot make the file creation list");
  check(H5Pset_file_space_strategy(creation.id(), H5F_FSPACE_STRATEGY_PAGE, 0, 1),
        "cannot ask for paged file space");
  check(H5Pset_file_space_page_size(creation.id(), kPage), "cannot set the file space page");
  return create_file(name, H5F_ACC_EXCL, access.id(), creation.id());
}

}  // namespace granpipe::h5
