#include "granpipe/bottom_wall.hpp"

#include "granpipe/errors.hpp"

namespace granpipe {

void require_bottom_wall(const Container& container, int vertical, const std::string& expected) {
  const Boundary bottom = container.boundary[vertical][0];
  if (bottom == Boundary::Wall) return;
  const std::string axis(1, "xyz"[vertical]);
  throw InputError(
      expected + ", got a container " +
      (bottom == Boundary::Periodic ? "periodic along " : "open at the bottom along ") + axis +
      " (state the wall where the source allows it)");
}

}  // namespace granpipe
