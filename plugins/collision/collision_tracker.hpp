#pragma once
// One collision followed frame by frame: the contact starts and ends where the overlap
// crosses zero, interpolated linearly between the frames on either side (the frames are
// one time step apart, where the overlap is nearly linear in time), and the restitution
// coefficient is the relative normal speed after the contact over the one before it, each
// taken in free flight (the frames just outside the contact).
#include <optional>
#include <string>

namespace granpipe::collision {

// The pair in one frame. overlap: R_1 + R_2 - |x_1 - x_2| (negative when apart);
// normal_velocity: (v_1 - v_2) . n with n from sphere 2 to sphere 1 (negative approaching);
// touching: the pair is in the frame's contact table.
struct PairState {
  double time = 0.0;
  double overlap = 0.0;
  double normal_velocity = 0.0;
  bool touching = false;
};

struct CollisionMeasure {
  double contact_time = 0.0;
  double restitution = 0.0;
  double approach_speed = 0.0;
  long frames_in_contact = 0;
};

class CollisionTracker {
 public:
  // Throws InputError starting with `where` (e.g. "frame 12") when the pair touches in the
  // first frame (no approach seen) or touches again after the collision.
  void add(const PairState& s, const std::string& where);
  // The collision; throws InputError starting with `where` (e.g. "collision: 431 frames")
  // when there was none or it had not ended by the last frame.
  CollisionMeasure result(const std::string& where) const;

 private:
  enum class Stage { Approach, Contact, Separated };
  Stage stage_ = Stage::Approach;
  std::optional<PairState> previous_;
  double start_ = 0.0, end_ = 0.0, speed_before_ = 0.0, speed_after_ = 0.0;
  long frames_in_contact_ = 0;
};

}  // namespace granpipe::collision
