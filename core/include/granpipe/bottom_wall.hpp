#pragma once
// Heights above a flat bottom wall. Stereology's cuts and its perturbed layer, compaction's
// <Z> and the Brazil-nut heights above the base all measure from the container's bottom:
// a container periodic or open at the bottom has none, and heights from an arbitrary side of
// the box came out as measured (exit 0). One check, so that each refuses the same
// containers in the same words.
#include <string>

#include "granpipe/container.hpp"

namespace granpipe {

// Throws InputError "<expected>, got a container periodic along z (state the wall where the
// source allows it)" (or "open at the bottom along z") unless the bottom along axis
// `vertical` is a wall. `expected` starts the message: "<where>: expected ...".
void require_bottom_wall(const Container& container, int vertical, const std::string& expected);

}  // namespace granpipe
