#include "h5_file.hpp"

#include <cstdlib>
#include <cstring>

namespace granpipe::h5 {

namespace {

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

Object create_file(const std::string& name, unsigned flags, hid_t access) {
  const hid_t id = H5Fcreate(name.c_str(), flags, H5P_DEFAULT, access);
  if (id >= 0) return Object(id);
  const std::string reason = system_reason();
  throw Error(
      "cannot create the file (" +
      (reason.empty() ? "does its directory exist, is it writable, is the disk full?" : reason) +
      ")");
}

}  // namespace granpipe::h5
