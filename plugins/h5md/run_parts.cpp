#include "run_parts.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

#include "granpipe/container.hpp"
#include "granpipe/errors.hpp"

namespace granpipe::h5md {
namespace {

std::vector<std::string> names_of(const std::vector<Property>& properties) {
  std::vector<std::string> names;
  for (const Property& p : properties) names.push_back(p.name);
  return names;
}

// What a later part must share with the first for its frames to continue the same run.
void require_same_content(const FrameFileInfo& first, const FrameFileInfo& later,
                          const std::string& name) {
  if (later.particles != first.particles || later.dim != first.dim) {
    throw InputError(name + ": " + later.path + ": expected frames of " +
                     std::to_string(first.particles) + " particles in " +
                     std::to_string(first.dim) + "D as " + first.path + " holds, got " +
                     std::to_string(later.particles) + " in " + std::to_string(later.dim) + "D");
  }
  if (names_of(later.columns) != names_of(first.columns) ||
      names_of(later.observables) != names_of(first.observables) ||
      later.has_contacts != first.has_contacts) {
    throw InputError(name + ": " + later.path + ": expected the columns of " + first.path +
                     " (the same run continued), got others");
  }
}

// A part named twice would pass as its own continuation (its first frame is one it holds)
// and read as one part: the slip of a copied path, refused.
void require_other_file(const std::vector<std::string>& files,
                        const std::vector<std::string>& names, std::size_t k) {
  for (std::size_t j = 0; j < k; ++j) {
    std::error_code error;
    if (files[j] == files[k] || std::filesystem::equivalent(files[j], files[k], error)) {
      throw InputError(names[k] + ": expected a later part of the run, got " + files[k] +
                       ", the file " + names[j] + " names");
    }
  }
}

bool same_container(const Container& a, const Container& b) {
  return a.shape == b.shape && a.lo == b.lo && a.hi == b.hi && a.boundary == b.boundary &&
         a.cylinder_radius == b.cylinder_radius && a.cylinder_center == b.cylinder_center &&
         a.wall_offset == b.wall_offset && a.wall_velocity == b.wall_velocity;
}

// How a later part's first frame differs from the saved frame it says it started from, or
// "" where it does not: the same positions with other ids, species, walls or clock were
// read as one run (ids renumbered mid-run, a periodic side turned into a wall).
std::string what_differs(const Frame& saved, const Frame& start) {
  if ((saved.position().array() != start.position().array()).any() ||
      (saved.radius() != start.radius()).any())
    return "another packing";
  if ((saved.id() != start.id()).any()) return "other particle ids";
  if ((saved.species() != start.species()).any()) return "other species";
  if (!same_container(saved.container, start.container)) return "another container";
  if (saved.time != start.time) return "another time";
  return "";
}

}  // namespace

RunParts::RunParts(const std::vector<std::string>& files, const std::vector<std::string>& names,
                   const std::string& group, double default_radius) {
  for (std::size_t k = 0; k < files.size(); ++k) {
    if (k) require_other_file(files, names, k);
    // The reader's refusals (not HDF5, not H5MD) name the file; the parameter too.
    try {
      parts_.push_back(std::make_unique<FrameReader>(files[k], group, default_radius));
    } catch (const InputError& e) {
      throw InputError(names[k] + ": " + e.what());
    }
    if (k && parts_[k]->frames() == 0) {
      throw InputError(names[k] + ": " + parts_[k]->info().path +
                       ": expected a part with frames (at least the one it started from), got "
                       "none");
    }
    if (k) require_same_content(first_info(), parts_[k]->info(), names[k]);
    append(k, names[k]);
  }
}

// The invariant kept: order_ lists every frame read so far once, steps rising. A later
// part's first frame is the saved frame it started from: the earlier part's frames after
// that one are dropped (a start from an earlier frame), and the earlier part's copy of it
// is kept, since it carries that tap's own observables.
void RunParts::append(std::size_t part, const std::string& name) {
  const FrameReader& reader = *parts_[part];
  if (part == 0) {
    for (long i = 0; i < reader.frames(); ++i) order_.push_back({0, i});
    return;
  }
  const Frame start = reader.read(0);
  std::optional<Frame> saved;       // the last frame kept so far, read once per step back
  std::size_t dropped_from = part;  // the earliest later part a frame was dropped from
  while (!order_.empty() && (saved = read(frames() - 1))->step > start.step) {
    if (order_.back().part > 0) dropped_from = order_.back().part;
    order_.pop_back();
  }
  const std::string not_continued = name + ": " + reader.info().path + " starts at step " +
                                    std::to_string(start.step) + ", expected a frame that ";
  // A restart from an earlier frame drops the frames after it; a whole part listed before
  // it dropped is a list out of order (or a part that should not be listed).
  if (dropped_from < part && (order_.empty() || order_.back().part < dropped_from)) {
    throw InputError(not_continued + "follows the part before it, got a step before every frame " +
                     "of " + parts_[dropped_from]->info().path +
                     " (list the parts in the order of the run, leaving out any replaced)");
  }
  if (order_.empty() || saved->step != start.step) {
    throw InputError(not_continued +
                     "the parts before it hold (not a continuation of them; a part holds first "
                     "the frame it started from, which a run saved without its start lacks)");
  }
  const std::string difference = what_differs(*saved, start);
  if (!difference.empty()) {
    throw InputError(not_continued + "the parts before it hold, got " + difference + " than " +
                     where(frames() - 1) + " (not a continuation of it)");
  }
  for (long i = 1; i < reader.frames(); ++i) order_.push_back({part, i});
}

Frame RunParts::read(long index) const {
  const FrameAddress& a = order_.at(static_cast<std::size_t>(index));
  return parts_[a.part]->read(a.index);
}

std::string RunParts::where(long index) const {
  const FrameAddress& a = order_.at(static_cast<std::size_t>(index));
  return parts_[a.part]->info().path + ": frame " + std::to_string(a.index);
}

}  // namespace granpipe::h5md
