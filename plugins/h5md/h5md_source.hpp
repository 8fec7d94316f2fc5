#pragma once
// `h5md`: saved frames as a source, so that any analyzer can reprocess them without
// simulating again. Reads granpipe's own frames.h5 bit for bit, and other tools' H5MD
// files (positions and the box; radii from the `radius` parameter). A run split over
// sessions is read from its parts as one.
#include <cstdint>
#include <optional>
#include <string>

#include "granpipe/frame_selection.hpp"
#include "granpipe/frame_store.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/time_order.hpp"
#include "run_parts.hpp"

namespace granpipe::h5md {

Schema schema();

class H5mdSource : public Source {
 public:
  explicit H5mdSource(const PluginContext& ctx);

  FrameContent content() const override;
  bool next(Frame& frame) override;
  Work work() const override;
  void finish(Results& results) override;

 private:
  // Hard-particle analyses are meaningless on overlapping particles: such input is refused
  // with the pair and the size of the overlap, unless max_overlap allows it.
  void check_overlaps(const Frame& frame, const std::string& where) const;
  void check_inside(const Frame& frame, const std::string& where) const;
  static void check_contacts_touch(const Frame& frame, const std::string& where);
  static void check_wall_contact_touches(const Frame& frame, Eigen::Index c,
                                         const std::string& where);
  static void check_pair_point(const Frame& frame, Eigen::Index c,
                               const Eigen::Ref<const Eigen::RowVectorXd>& point, double smaller,
                               const std::string& where);
  Frame read_checked(long index) const;
  void check_step_rises(const Frame& frame, long index);
  RunParts parts_;
  FrameSelection selection_;
  long next_ = 0, read_ = 0;
  double max_overlap_;
  std::string max_overlap_param_;  // its path in the pipeline, for the message
  std::optional<Frame> first_frame_;
  // Steps rise from frame to frame (one file, or the parts of a run): the last frame read.
  std::string file_param_, continued_param_;
  std::optional<std::int64_t> last_step_;
  TimeOrder time_order_;
  long last_index_ = -1;
};

}  // namespace granpipe::h5md
