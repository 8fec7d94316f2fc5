#pragma once
// Ownership of one HDF5 identifier (file, group, dataset, dataspace, datatype, property
// list, attribute), so that every exit path, exceptions included, releases it.
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "granpipe/errors.hpp"

namespace granpipe::h5 {

// A failed HDF5 operation. The message names the object ("<path>: <what went wrong>");
// the frame store adds the file name and turns it into an InputError.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Object {
 public:
  Object() = default;
  explicit Object(hid_t id) : id_(id) {}
  ~Object() { reset(); }
  Object(Object&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;

  hid_t id() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Gives up ownership (after the caller closed it with a checked call).
  hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }
  // Dropping the last reference closes the object whatever its kind.
  void reset() {
    if (id_ >= 0) H5Idec_ref(id_);
    id_ = H5I_INVALID_HID;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
};

// Takes ownership of `id`, or throws Error("<what>") when the call that made it failed.
inline Object owned(hid_t id, const std::string& what) {
  if (id < 0) throw Error(what);
  return Object(id);
}

inline void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error(what);
}

// HDF5 prints its whole error stack to stderr by default; granpipe reports one line
// instead. The setting is per thread in a thread-safe HDF5, so every entry point calls it.
inline void silence_error_stack() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// Runs `f`, turning an h5::Error into the one-line InputError "<file>: <path>: <what>".
template <class F>
auto input_errors_of(const std::string& file, F&& f) {
  try {
    return f();
  } catch (const Error& e) {
    throw InputError(file + ": " + e.what());
  }
}

}  // namespace granpipe::h5
