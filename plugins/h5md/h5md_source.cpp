#include "h5md_source.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/deepest_overlap.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/particles_outside.hpp"
#include "granpipe/separation.hpp"

namespace granpipe::h5md {

namespace {
constexpr double kDefaultRadius = 0.5;
}  // namespace

Schema schema() {
  Schema s;
  s.path("file", std::nullopt, "the H5MD file to read (a granpipe frames.h5 or another tool's)");
  s.paths("continued_in", std::vector<std::string>{},
          "the later parts of a run split over sessions, in order, each started from a saved "
          "frame of the part before it (spheres3d_tap's continue_count): read on as one run");
  declare_frame_selection(s);
  s.string("group", std::string(""),
           "particles group of the file (/particles/<group>); empty: \"all\" or the only one");
  s.real("radius", kDefaultRadius,
         "radius of every particle when the file stores none (other tools' files)")
      .range(1e-50, 1e50)
      .unit("length");
  s.real("max_overlap", 1e-6,
         "largest overlap accepted between two particles, as a fraction of the smaller radius, "
         "and between a particle and a wall, as a fraction of its radius: about 0 for hard "
         "particles, a few percent for soft-sphere (DEM) data")
      .min(0.0);
  return s;
}

namespace {

// " and 2 continuations" after the first file's name, or nothing.
std::string held_by_parts(const RunParts& parts) {
  const auto later = parts.parts().size() - 1;
  if (later == 0) return "";
  return " and " + std::to_string(later) + (later == 1 ? " continuation" : " continuations");
}

std::vector<std::string> part_files(const PluginContext& ctx) {
  std::vector<std::string> files{ctx.params.string("file")};
  for (const std::string& f : ctx.params.paths("continued_in")) files.push_back(f);
  return files;
}

std::vector<std::string> part_names(const PluginContext& ctx) {
  std::vector<std::string> names{ctx.param("file")};
  const auto later = ctx.params.paths("continued_in").size();
  for (std::size_t k = 0; k < later; ++k)
    names.push_back(ctx.param("continued_in") + "[" + std::to_string(k) + "]");
  return names;
}

void warn_unfinished(const PluginContext& ctx, const RunParts& parts) {
  for (const auto& part : parts.parts()) {
    const FrameFileInfo& info = part->info();
    if (info.complete) continue;
    ctx.log.warn(info.path +
                 ": the writer never finished this file (stopped or crashed); "
                 "reading the " +
                 std::to_string(info.frames) + " frames it completed");
  }
}

// A radius given for a file that stores its own did nothing, without a word.
void refuse_unused_radius(const PluginContext& ctx, const FrameFileInfo& info) {
  const double radius = ctx.params.real("radius");
  const bool stored = std::any_of(info.columns.begin(), info.columns.end(),
                                  [](const Property& p) { return p.name == "radius"; });
  if (!stored || radius == kDefaultRadius) return;
  throw InputError(ctx.param("radius") + ": expected its default " + format_number(kDefaultRadius) +
                   " for a file that stores radii (" + info.path + "), got " +
                   format_number(radius));
}

// Positions or radii stored as 32-bit floats (other tools' files) are known to 2^-24 of
// their size: contacts found from them by distance (contact_tolerance, 1e-9 of the contact
// distance by default) were missed without a word (packing's z of an FCC crystal: 4 for 12),
// and so pores of one site were counted apart.
void warn_if_single_precision(const PluginContext& ctx, const FrameFileInfo& info,
                              const Frame& first) {
  const bool positions = info.position_bytes < 8, radii = info.radius_bytes < 8;
  if (!positions && !radii) return;
  const double largest = positions ? first.position().abs().maxCoeff() : first.radius().maxCoeff();
  const double rounding = largest * std::ldexp(1.0, -24);
  const double contact = 2.0 * first.radius().minCoeff();
  const std::string what = positions && radii ? "positions and radii"
                           : positions        ? "positions"
                                              : "radii";
  const int bytes = positions ? info.position_bytes : info.radius_bytes;
  ctx.log.warn(info.path + ": " + what + " stored as " + std::to_string(8 * bytes) +
               "-bit floats: " + (positions ? "a coordinate" : "a radius") + " is known to " +
               format_number(rounding) + ", " + format_number(rounding / contact) +
               " of the smallest contact distance, coarser than the contact_tolerance " +
               format_number(kDefaultContactTolerance) +
               " by which analyzers find contacts from positions (and than pores' tolerance): " +
               (info.has_contacts ? "" : "give the frames' contacts, or ") +
               "raise those tolerances above it");
}

}  // namespace

H5mdSource::H5mdSource(const PluginContext& ctx)
    : parts_(part_files(ctx), part_names(ctx), ctx.params.string("group"),
             ctx.params.real("radius")),
      max_overlap_(ctx.params.real("max_overlap")),
      max_overlap_param_(ctx.param("max_overlap")),
      file_param_(ctx.param("file")),
      continued_param_(ctx.param("continued_in")) {
  const FrameFileInfo& info = parts_.first_info();
  const long frames = parts_.frames();
  const std::string held = " (" + info.path + held_by_parts(parts_) +
                           (parts_.parts().size() > 1 ? " hold " : " holds ") +
                           std::to_string(frames) + " frames)";
  if (frames == 0)
    throw InputError(ctx.param("file") + ": expected a file with frames, got none" + held);
  selection_ = select_frames(ctx, frames, held);
  warn_unfinished(ctx, parts_);
  refuse_unused_radius(ctx, info);
  next_ = selection_.first;
  // The first frame is read and checked now, so that bad particles stop the pipeline at
  // validation, before anything runs.
  first_frame_ = read_checked(selection_.first);
  warn_if_single_precision(ctx, info, *first_frame_);
}

Frame H5mdSource::read_checked(long index) const {
  Frame frame = parts_.read(index);
  const std::string where = parts_.where(index);
  frame.check(where);
  // Every measure of an empty frame is 0/0.
  if (frame.size() == 0) throw InputError(where + ": expected particles, got none");
  check_overlaps(frame, where);
  check_inside(frame, where);
  if (frame.contacts) check_contacts_touch(frame, where);
  return frame;
}

FrameContent H5mdSource::content() const {
  const FrameFileInfo& info = parts_.first_info();
  FrameContent content{.dim = info.dim, .contacts = info.has_contacts, .columns = info.columns};
  content.columns.insert(content.columns.end(), info.observables.begin(), info.observables.end());
  content.columns.insert(content.columns.end(), info.contact_columns.begin(),
                         info.contact_columns.end());
  return content;
}

Source::Work H5mdSource::work() const {
  return {static_cast<double>(selection_.count()), "frames", false};
}

bool H5mdSource::next(Frame& frame) {
  if (next_ > selection_.last) return false;
  if (first_frame_) {
    frame = std::move(*first_frame_);
    first_frame_.reset();
  } else {
    frame = read_checked(next_);
  }
  check_step_rises(frame, next_);
  next_ += selection_.stride;
  ++read_;
  return true;
}

// Frames whose steps go back or repeat (a part copying an earlier part's frames, a session
// started from a frame other than its first, a file written out of order) would count
// taps twice, or in the wrong order, in every analysis over the run. Their times follow
// (a file of another tool whose times ran down gave the intruder's lift-offs backwards).
void H5mdSource::check_step_rises(const Frame& frame, long index) {
  const bool steps_back = last_step_ && frame.step <= *last_step_;
  if (steps_back || time_order_.runs_back(frame.time)) {
    const bool parts = parts_.parts().size() > 1;
    const std::string place = (parts ? continued_param_ : file_param_) + ": " +
                              parts_.where(index) + ": expected a ",
                      before = " (" + parts_.where(last_index_) + ", the frame read before it";
    if (steps_back) {
      throw InputError(place + "step above " + std::to_string(*last_step_) + before + ": " +
                       (parts ? "the parts are one run, steps rising" : "a run's steps rise") +
                       "), got " + std::to_string(frame.step));
    }
    throw InputError(place + "time at or after " + format_number(time_order_.last()) + before +
                     "), got " + format_number(frame.time));
  }
  last_step_ = frame.step;
  time_order_.pass(frame.time);
  last_index_ = index;
}

void H5mdSource::check_overlaps(const Frame& frame, const std::string& where) const {
  const auto deepest = deepest_pair_overlap(frame, where);
  if (!deepest || deepest->fraction <= max_overlap_) return;
  const auto i = deepest->i, j = deepest->j;
  std::ostringstream msg;
  msg << where << ": particles " << i << " and " << j << " (ids " << frame.id()[i] << ", "
      << frame.id()[j] << ") overlap by " << deepest->fraction
      << " of the smaller radius, expected at most " << max_overlap_ << " (raise "
      << max_overlap_param_ << " for soft-particle data)";
  throw InputError(msg.str());
}

// A particle through a wall is in no container the analyses can measure (a packing
// fraction of 0.02 for a block behind a wall, exit 0). Walls are judged with the particles'
// tolerance: soft-sphere data press into them too. An open side is no wall: a particle
// thrown above an open top is in the container.
void H5mdSource::check_inside(const Frame& frame, const std::string& where) const {
  const auto out = first_particle_outside(frame, max_overlap_, false);
  if (!out) return;
  std::ostringstream msg;
  msg << where << ": particle " << out->particle << " (id " << frame.id()[out->particle] << ") "
      << describe(frame, *out, max_overlap_) << " (" << max_overlap_param_
      << " sets the overlap accepted with a wall)";
  throw InputError(msg.str());
}

// A contact joins particles that touch: one between particles a whole radius (of the
// smaller) or more apart is no contact under any writer's rounding, and entered the
// networks as a bond (a contact to a particle 80 diameters away joined it to the largest).
// A wall contact likewise (the top particle's "base contact", 86 above the base, was
// counted as one).
void H5mdSource::check_contacts_touch(const Frame& frame, const std::string& where) {
  const IndexArray &i = frame.contact_i(), &j = frame.contact_j();
  const Column* point = frame.contacts->find("point");
  for (Eigen::Index c = 0; c < i.size(); ++c) {
    if (!partner::is_particle(j[c])) {
      check_wall_contact_touches(frame, c, where);
      continue;
    }
    const double ri = frame.radius()[i[c]], rj = frame.radius()[j[c]];
    const double gap = separation(frame, i[c], j[c]).norm() - ri - rj;
    const double smaller = std::min(ri, rj);
    if (!(gap > smaller)) {
      if (point) check_pair_point(frame, c, point->as<Coordinates>().row(c), smaller, where);
      continue;
    }
    throw InputError(where + ": contact " + std::to_string(c) +
                     ": expected particles that touch, got " + std::to_string(i[c]) + " and " +
                     std::to_string(j[c]) + " (ids " + std::to_string(frame.id()[i[c]]) + ", " +
                     std::to_string(frame.id()[j[c]]) + "), whose surfaces are " +
                     format_number(gap) + " apart (more than the smaller radius, " +
                     format_number(smaller) + ")");
  }
}

// A pair contact's point, where the table gives one, lies where the two touch: within the
// smaller radius of either's surface, as the particles themselves must be. A point a million
// radii away made the force network's F(r) bins of that contact NaN, exit 0.
void H5mdSource::check_pair_point(const Frame& frame, Eigen::Index c,
                                  const Eigen::Ref<const Eigen::RowVectorXd>& point, double smaller,
                                  const std::string& where) {
  for (const std::int64_t k : {frame.contact_i()[c], frame.contact_j()[c]}) {
    const double gap = separation_to(frame, k, point).norm() - frame.radius()[k];
    if (!(gap > smaller)) continue;
    throw InputError(
        where + ": contact " + std::to_string(c) + ": expected its point where particles " +
        std::to_string(frame.contact_i()[c]) + " and " + std::to_string(frame.contact_j()[c]) +
        " touch, got it " + format_number(gap) + " from the surface of particle " +
        std::to_string(k) + " (id " + std::to_string(frame.id()[k]) +
        "; more than the smaller radius, " + format_number(smaller) + ")");
  }
}

// Where the table gives the contact point, the wall was there (a mesh wall, a moving base
// that the stated container only approximates: a LIGGGHTS run's base shaken by 0.8 mm and
// stated at its lowest); else where the container has it.
void H5mdSource::check_wall_contact_touches(const Frame& frame, Eigen::Index c,
                                            const std::string& where) {
  const std::int64_t k = frame.contact_i()[c];
  const Wall wall = partner::wall_of(frame.contact_j()[c]);
  const double radius = frame.radius()[k];
  const Column* point = frame.contacts->find("point");
  double gap;
  if (point) {
    gap = separation_to(frame, k, point->as<Coordinates>().row(c)).norm() - radius;
  } else {
    gap = surface_gap(frame, k, wall);
  }
  if (!(gap > radius)) return;
  throw InputError(where + ": contact " + std::to_string(c) + ": expected particle " +
                   std::to_string(k) + " (id " + std::to_string(frame.id()[k]) +
                   ") to touch the wall " + to_string(wall) + ", got its surface " +
                   format_number(gap) + " from " + (point ? "the contact's point" : "it") +
                   " (more than its radius, " + format_number(radius) + ")");
}

void H5mdSource::finish(Results& results) {
  results.add_scalar("frames_read", static_cast<double>(read_), std::nan(""), "",
                     "frames read from " + parts_.first_info().path + held_by_parts(parts_));
  results.add_scalar("particles", static_cast<double>(parts_.first_info().particles), std::nan(""),
                     "", "particles per frame");
}

}  // namespace granpipe::h5md
