#include "collision_tracker.hpp"

#include "granpipe/errors.hpp"

namespace granpipe::collision {

namespace {

// Where the overlap crosses zero between two frames, linearly.
double zero_crossing(const PairState& a, const PairState& b) {
  return a.time + (b.time - a.time) * a.overlap / (a.overlap - b.overlap);
}

}  // namespace

void CollisionTracker::add(const PairState& s, const std::string& where) {
  switch (stage_) {
    case Stage::Approach:
      if (s.touching) {
        if (!previous_) {
          throw InputError(where +
                           ": expected the spheres apart in the first frame (the approach "
                           "before the collision), got them touching");
        }
        start_ = zero_crossing(*previous_, s);
        speed_before_ = -previous_->normal_velocity;
        stage_ = Stage::Contact;
      }
      break;
    case Stage::Contact:
      if (!s.touching) {
        end_ = zero_crossing(*previous_, s);
        speed_after_ = s.normal_velocity;
        stage_ = Stage::Separated;
      }
      break;
    case Stage::Separated:
      if (s.touching) {
        throw InputError(where + ": expected one collision, got a second contact of the pair");
      }
      break;
  }
  if (s.touching) ++frames_in_contact_;
  previous_ = s;
}

CollisionMeasure CollisionTracker::result(const std::string& where) const {
  if (stage_ == Stage::Approach)
    throw InputError(where + ": expected the two spheres to collide, got no contact");
  if (stage_ == Stage::Contact) {
    throw InputError(where +
                     ": expected the contact to end by the last frame, got the spheres still "
                     "touching (a longer duration?)");
  }
  return {end_ - start_, speed_after_ / speed_before_, speed_before_, frames_in_contact_};
}

}  // namespace granpipe::collision
