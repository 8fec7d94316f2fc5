#pragma once
// A run split over sessions (a source continued from a saved frame, e.g. spheres3d_tap's
// continue_count) leaves one frames file per part, each later part beginning with the
// frame it started from. Read in order they are one run: each frame once, steps rising.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "granpipe/frame_store.hpp"

namespace granpipe::h5md {

struct FrameAddress {
  std::size_t part = 0;
  long index = 0;  // within the part's file
};

class RunParts {
 public:
  // `files[0]` is the first part; `names[k]` says where the pipeline names `files[k]`, for
  // messages. InputError when a part is not a continuation of the one before it: other
  // particles or columns, no frame at the step it starts from, or another packing there; or
  // when it is a file named before it. (That steps rise within a part is checked as frames
  // are read: H5mdSource.)
  RunParts(const std::vector<std::string>& files, const std::vector<std::string>& names,
           const std::string& group, double default_radius);

  const FrameFileInfo& first_info() const { return parts_.front()->info(); }
  const std::vector<std::unique_ptr<FrameReader>>& parts() const { return parts_; }
  long frames() const { return static_cast<long>(order_.size()); }
  Frame read(long index) const;
  // Where frame `index` lives, for messages: "run.h5: frame 12".
  std::string where(long index) const;

 private:
  void place_walls_alike();
  void append(std::size_t part, const std::string& name);
  std::vector<std::unique_ptr<FrameReader>> parts_;
  std::vector<FrameAddress> order_;
};

}  // namespace granpipe::h5md
