#pragma once
// The error of a run that blew up or went unsound while it ran.
#include "granpipe/errors.hpp"

namespace granpipe::dem {

// An InputError: with validated parameters it is the time step, the stiffness against the
// speeds, or the initial overlaps that the user must change, and the message says so.
class BlowUp : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace granpipe::dem
