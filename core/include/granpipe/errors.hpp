#pragma once
// The two error types of granpipe. The executable maps InputError to exit code 2
// and everything else to exit code 1, and prints the message as one line.
#include <stdexcept>
#include <string>

namespace granpipe {

// Something the user can fix: a malformed pipeline, a missing file, bad particles.
// The message names where (file, JSON path or dataset), what was expected, what was found.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A bug in granpipe or in a plugin.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace granpipe
