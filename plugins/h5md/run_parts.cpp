#include "run_parts.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "granpipe/container.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

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

// How `here` differs from `there` ("" where it does not), one field with both values. The
// box's place is compared only where both files store it: another tool's H5MD box has no
// origin, and each part's reader places its walls from its own frames.
std::string container_difference(const Container& here, const Container& there, bool placed) {
  const auto differ = [](const std::string& field, const std::string& a, const std::string& b) {
    return field + " " + a + ", there " + b;
  };
  if (here.shape != there.shape)
    return differ("shape", to_string(here.shape), to_string(there.shape));
  for (int a = 0; a < 3; ++a) {
    const std::string axis(1, "xyz"[a]);
    for (int side = 0; side < 2; ++side) {
      const Boundary h = here.boundary[a][side], t = there.boundary[a][side];
      if (h != t) return differ("boundary along " + axis, to_string(h), to_string(t));
    }
    const bool moved = here.lo[a] != there.lo[a] || here.hi[a] != there.hi[a];
    if (placed ? moved : here.length(a) != there.length(a)) {
      return differ("extent along " + axis,
                    format_number(here.lo[a], 17) + " to " + format_number(here.hi[a], 17),
                    format_number(there.lo[a], 17) + " to " + format_number(there.hi[a], 17));
    }
  }
  if (here.cylinder_radius != there.cylinder_radius ||
      here.cylinder_center != there.cylinder_center)
    return differ("cylinder radius", format_number(here.cylinder_radius, 17),
                  format_number(there.cylinder_radius, 17) + " (or its axis)");
  if (here.wall_offset != there.wall_offset)
    return differ("wall offset", format_point(here.wall_offset, 17),
                  format_point(there.wall_offset, 17));
  if (here.wall_velocity != there.wall_velocity)
    return differ("wall velocity", format_point(here.wall_velocity, 17),
                  format_point(there.wall_velocity, 17));
  return "";
}

// The first row where two columns differ, or -1.
template <class Column>
Eigen::Index first_difference(const Column& a, const Column& b) {
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) return i;
  return -1;
}

// How a later part's first frame (`start`) differs from the saved frame it says it started
// from, as what and its detail; empty where it does not: the same positions with other ids,
// species, walls or clock were read as one run (ids renumbered mid-run, a periodic side
// turned into a wall). `placed`: both files store their container's place.
std::pair<std::string, std::string> what_differs(const Frame& saved, const Frame& start,
                                                 bool placed) {
  if ((saved.position().array() != start.position().array()).any() ||
      (saved.radius() != start.radius()).any())
    return {"another packing", ""};
  const auto row = [](Eigen::Index i, auto here, auto there) {
    return "row " + std::to_string(i) + ": " + std::to_string(here) + ", there " +
           std::to_string(there);
  };
  if (const Eigen::Index i = first_difference(start.id(), saved.id()); i >= 0)
    return {"other particle ids", row(i, start.id()[i], saved.id()[i])};
  if (const Eigen::Index i = first_difference(start.species(), saved.species()); i >= 0)
    return {"other species", row(i, start.species()[i], saved.species()[i])};
  const std::string container = container_difference(start.container, saved.container, placed);
  if (!container.empty()) return {"another container", container};
  // NaN is an undefined time (a dump read without dt): the same in both.
  const bool undefined = std::isnan(saved.time) && std::isnan(start.time);
  if (saved.time != start.time && !undefined) {
    return {"another time", "time " + format_number(start.time, 17) + ", there " +
                                format_number(saved.time, 17) +
                                " (a converter run with another dt?)"};
  }
  return {};
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
  }
  place_walls_alike();
  for (std::size_t k = 0; k < files.size(); ++k) append(k, names[k]);
}

// Another tool's parts store no origin, and each placed its walls where its own frames fit:
// a part whose frames fit both placements took [0, L] while the next one's frames fit
// [-L/2, L/2] only, and a genuine continuation was refused. The placement every part's
// frames allow is taken for all (where none is, the parts are refused at their join).
void RunParts::place_walls_alike() {
  for (const auto& part : parts_)
    if (part->info().granpipe_file) return;
  std::array<bool, 3> settled{}, centred{};
  for (int a = 0; a < 3; ++a) {
    bool at_zero = true, centre = true;
    for (const auto& part : parts_) {
      at_zero = at_zero && part->wall_placements().at_zero[a];
      centre = centre && part->wall_placements().centred[a];
    }
    settled[a] = at_zero || centre;  // else each part keeps its own, refused at the join
    centred[a] = !at_zero;
  }
  for (const auto& part : parts_) part->place_walls_like(settled, centred);
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
  // Another tool's parts store no origin: placed alike where a placement holds all their
  // frames (place_walls_alike), else apart (walls that jump by L/2), which is not one run.
  const bool granpipe = first_info().granpipe_file, also = reader.info().granpipe_file;
  const bool foreign = !granpipe && !also;
  auto [difference, detail] = what_differs(*saved, start, granpipe == also);
  bool same_edges = true;
  for (int a = 0; a < 3; ++a)
    same_edges = same_edges && saved->container.length(a) == start.container.length(a);
  if (foreign && same_edges && difference == "another container")
    detail += "; H5MD stores no origin, and no place of the walls holds every part's frames";
  if (!difference.empty()) {
    throw InputError(not_continued + "the parts before it hold, got " + difference + " than " +
                     where(frames() - 1) + " (" + (detail.empty() ? "" : detail + "; ") +
                     "not a continuation of it)");
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
