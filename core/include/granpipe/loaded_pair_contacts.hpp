#pragma once
// The contacts of a frame that join two particles and carry a normal force, and the frame
// choice made on them: the analyzers that report one frame in full (mst's Table II,
// force_network's PDF and F(r)) report the frame with the most loaded pair contacts, the
// earliest of equals, so that they describe the same instant.
#include <cstdint>
#include <string>
#include <vector>

#include "granpipe/frame.hpp"

namespace granpipe {

// The rows of the frame's contact table that join two particles with a non-zero normal
// force, ascending (every particle-particle row when the table has no normal_force
// column); none for a frame without a contact table. Throws InputError
// "<where>: contact K: ..." for a row that joins a particle to itself or a normal force
// that is NaN or infinite (wall rows too).
std::vector<Eigen::Index> loaded_pair_contacts(const Frame& frame, const std::string& where);

// Offered every frame's count of loaded pair contacts in order, keeps the frame with the
// most, the earliest of equals.
class MostLoadedFrame {
 public:
  // True when `loaded` is more than every earlier frame's (always for the first frame):
  // the frame becomes the chosen one, and the caller keeps what it reports of it.
  bool offer(long frame, std::int64_t loaded);
  long frame() const { return frame_; }  // -1 before the first offer
  std::int64_t loaded() const { return loaded_; }

 private:
  long frame_ = -1;
  std::int64_t loaded_ = -1;
};

}  // namespace granpipe
