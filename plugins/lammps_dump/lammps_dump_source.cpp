#include "lammps_dump_source.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/deepest_overlap.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/text_words.hpp"
#include "snapshot_atoms.hpp"

namespace granpipe::lammps_dump {

namespace {

std::vector<std::string> keywords(const std::string& text) {
  std::vector<std::string> out;
  for (std::string_view w : words(text)) out.emplace_back(w);
  return out;
}

// LAMMPS writes a 2D run's atoms at z = 0 in a box periodic along z, whose z bounds
// straddle 0 (any thickness: a run with disks of 1 mm in z bounds of -5 to 5 mm was read as
// spheres, exit 0). No 3D packing has a period along z of at most an atom's diameter (the
// atom would touch its own image); one lying exactly in the plane z = 0 of a straddling
// periodic box cannot be told from a 2D run, as in lammps_data: the message says how to
// have it read.
void refuse_a_2d_run(const Frame& f, const Container& box, const std::string& at) {
  const auto z = f.position().col(2);
  const double diameter = 2.0 * f.radius().maxCoeff();
  if (!box.periodic(2) || (z != z[0]).any()) return;
  if (box.length(2) <= diameter) {
    throw InputError(at + kReads3d + "every atom at z = " + format_number(z[0]) +
                     " in a box periodic along z and " + format_number(box.length(2)) +
                     " thick, no more than an atom's diameter (" + format_number(diameter) +
                     "): a 2D run's dump");
  }
  if (z[0] != 0.0 || !(box.lo[2] < 0.0 && box.hi[2] > 0.0)) return;
  throw InputError(at + kReads3d + "every atom at z = 0 in a box periodic along z from " +
                   format_number(box.lo[2]) + " to " + format_number(box.hi[2]) +
                   ": a 2D run's dump (a 3D packing in the plane z = 0 cannot be told from one: "
                   "shift its atoms and box off z = 0 to have it read)");
}

}  // namespace

Schema schema() {
  Schema s;
  s.path("file", std::nullopt,
         "LAMMPS or LIGGGHTS text dump (dump custom or dump atom), plain or gzip-compressed");
  declare_frame_selection(s);
  s.real("radius", 0.0,
         "radius of every atom of a dump without a radius or diameter column (0: the dump's)")
      .min(0.0)
      .unit("length");
  s.real("dt", 0.0,
         "the run's timestep: a frame's time is TIMESTEP x dt in dumps without ITEM: TIME (0: "
         "the time is undefined, NaN)")
      .min(0.0)
      .unit("time");
  declare_stated_container(s);
  declare_max_overlap(
      s, 0.3,
      "a sound soft-sphere run stays within 0.3; a snapshot with a deeper one (atoms "
      "stacked at one place) is refused");
  s.path("pair_file", std::string(""),
         "dump local of the pair contacts at the atom dump's timesteps (LIGGGHTS compute "
         "pair/gran/local, or LAMMPS compute property/local patom1 patom2 and pair/local); "
         "\"\": no contacts");
  const auto with_contacts = [](const Params& p) {
    return !p.string("pair_file").empty() || !p.string("wall_file").empty();
  };
  s.choice<ContactFormat>("pair_format", ContactFormat::Liggghts,
                          "the code that wrote pair_file and wall_file")
      .only_where("a pair_file or wall_file", with_contacts);
  s.string("pair_columns", "",
           "the keywords of the computes that wrote pair_file, as in the input script: "
           "LIGGGHTS \"pos id force force_normal contactArea delta\" (any order), LAMMPS "
           "one per column \"patom1 patom2 dist fx fy fz p1 p2 p3\"")
      .only_where("a pair_file", [](const Params& p) { return !p.string("pair_file").empty(); });
  s.path(
      "wall_file", std::string(""),
      "dump local of LIGGGHTS compute wall/gran/local at the atom dump's timesteps (\"\": "
      "none); each contact goes to the stated wall its pos faces (without pos: nearest its atom)");
  s.string("wall_columns", "", "the keywords of compute wall/gran/local, as pair_columns")
      .only_where("a wall_file", [](const Params& p) { return !p.string("wall_file").empty(); });
  return s;
}

LammpsDumpSource::LammpsDumpSource(const PluginContext& ctx)
    : file_(ctx.params.string("file")),
      stated_(ctx),
      radius_(ctx.params.real("radius")),
      dt_(ctx.params.real("dt")),
      dt_param_(ctx.param("dt")),
      max_overlap_(ctx.params.real("max_overlap")),
      max_overlap_param_(ctx.param("max_overlap")),
      lines_(file_),
      index_(complete_snapshots(lines_)),
      columns_(parse_atom_columns(index_.columns, index_.columns_at)) {
  const long snapshots = static_cast<long>(index_.snapshots.size());
  warn_if_cut(ctx);
  check_radius(ctx);
  open_contact_dumps(ctx);
  selection_ = select_frames(ctx, snapshots,
                             " (" + file_ + " holds " + std::to_string(snapshots) + " snapshots)");
  next_ = selection_.first;
  first_frame_ = read_snapshot(selection_.first);
  if (!pairs_) warn_if_coarse(ctx, *first_frame_);
  // A dt beside the dump's own times (which LAMMPS counts from the run's start, through
  // reset_timestep and changes of dt) was dropped without a word.
  if (*times_stated_ && dt_ > 0) {
    ctx.log.warn(file_ + ": " + dt_param_ + " is not used: the dump states its times (ITEM: TIME)");
  }
  // Undefined times are NaN in every table with a time column: said once, with the cure.
  if (std::isnan(first_frame_->time)) {
    ctx.log.warn(file_ + ": the dump has no ITEM: TIME and " + dt_param_ +
                 " is 0: times are undefined (NaN in the results); give the run's timestep "
                 "as " +
                 dt_param_);
  }
}

// Two centres each off by up to the rounding of a position: their distance by up to twice
// that.
double LammpsDumpSource::distance_rounding(const PositionPrecision& precision,
                                           const Frame& f) const {
  std::array<double, 3> scale{1.0, 1.0, 1.0};
  for (int a = 0; a < 3; ++a) {
    const bool scaled = columns_.coordinate[a] == Coordinate::Scaled ||
                        columns_.coordinate[a] == Coordinate::ScaledUnwrapped;
    if (scaled) scale[a] = f.container.length(a);
  }
  const std::array<double, 3> r = precision.rounding(scale);
  return 2.0 * std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
}

void LammpsDumpSource::warn_if_coarse(const PluginContext& ctx, const Frame& first) const {
  const double rounding = distance_rounding(precision_, first);
  const double contact = 2.0 * first.radius().minCoeff();
  const double relative = rounding / contact;
  if (relative <= kDefaultContactTolerance) return;
  ctx.log.warn(file_ + ": positions printed to " + std::to_string(precision_.significant()) +
               " significant digits: a centre distance is known to " + format_number(rounding) +
               ", " + format_number(relative) + " of the smallest contact distance (" +
               format_number(contact) + "), coarser than the contact_tolerance " +
               format_number(kDefaultContactTolerance) +
               " by which analyzers find contacts from positions: give the run's contacts "
               "(pair_file) or write positions with dump_modify format float %.17g");
}

void LammpsDumpSource::add_contacts(Frame& f, const PositionPrecision& precision) {
  if (!pairs_ && !walls_) return;
  const std::string place = "timestep " + std::to_string(f.step) + " of " + file_;
  const double rounding = distance_rounding(precision, f);
  std::vector<ContactRow> rows;
  if (pairs_) pairs_->read(f, place, rounding, rows);
  if (walls_) walls_->read(f, place, rounding, rows);
  fill_contact_table(rows, tangential(), f);
}

void LammpsDumpSource::open_contact_dumps(const PluginContext& ctx) {
  const auto format = ctx.params.choice<ContactFormat>("pair_format");
  auto open = [&](const char* file, const char* columns,
                  bool wall) -> std::unique_ptr<ContactDump> {
    const std::string& path = ctx.params.string(file);
    if (path.empty()) return nullptr;
    const std::string& given = ctx.params.string(columns);
    if (given.empty()) {
      throw InputError(ctx.param(columns) + ": expected the keywords of the compute that wrote " +
                       path + ", got none");
    }
    if (wall && format == ContactFormat::Lammps) {
      throw InputError(ctx.param(file) +
                       ": expected no wall file with pair_format \"lammps\" "
                       "(LAMMPS has no compute of wall contacts), got " +
                       path);
    }
    auto dump = std::make_unique<ContactDump>(
        path, contact_columns(format, keywords(given), wall, ctx.param(columns)), wall,
        ctx.param(columns));
    dump->check_timesteps(index_, file_);
    return dump;
  };
  pairs_ = open("pair_file", "pair_columns", false);
  walls_ = open("wall_file", "wall_columns", true);
}

FrameContent LammpsDumpSource::content() const {
  FrameContent c{.dim = 3, .contacts = pairs_ || walls_, .columns = columns_.properties()};
  if (!c.contacts) return c;
  std::vector<const char*> names{"overlap", "normal_force", "point"};
  if (tangential()) names.push_back("tangential_force");
  for (const char* name : names) c.columns.push_back(*find_standard(name, Scope::Contact));
  return c;
}

bool LammpsDumpSource::tangential() const {
  return (!pairs_ || pairs_->has_tangential()) && (!walls_ || walls_->has_tangential());
}

void LammpsDumpSource::warn_if_cut(const PluginContext& ctx) const {
  const std::string complete =
      "reading the " + std::to_string(index_.snapshots.size()) + " complete snapshots before it";
  if (index_.cut) {
    ctx.log.warn(file_ + ": the file ends inside " + index_.cut->name() +
                 ", as when its writer is stopped: " + complete);
  } else if (index_.ended_early) {
    ctx.log.warn(file_ + ": the compressed data end early (the file was cut): " + complete);
  }
}

void LammpsDumpSource::check_radius(const PluginContext& ctx) const {
  if (columns_.size < 0 && radius_ == 0) {
    throw InputError(index_.columns_at + "expected a radius or diameter column (or " +
                     ctx.param("radius") + " for a dump without one), got none");
  }
  if (columns_.size >= 0 && radius_ > 0) {
    throw InputError(ctx.param("radius") + ": expected 0 for a dump with a " +
                     (columns_.diameter ? "diameter" : "radius") + " column (" + file_ + "), got " +
                     format_number(radius_));
  }
}

Frame LammpsDumpSource::read_snapshot(long index) {
  const SnapshotStart& start = index_.snapshots[static_cast<std::size_t>(index)];
  lines_.seek(start.offset, start.line_before);
  try {
    std::string line;
    next_line_of(SnapshotPlace{file_, start.line_before + 1}, lines_, line);
    return frame_of(read_header(file_, lines_, line));
  } catch (const SnapshotCut& cut) {
    throw InputError(file_ + ": expected " + cut.place.name() +
                     " to be complete, as it was when the source started, got a shorter file");
  }
}

Frame LammpsDumpSource::frame_of(const SnapshotHeader& h) {
  SnapshotAtoms atoms = read_atoms(h, columns_, radius_, lines_);
  Frame& f = atoms.frame;
  if (f.size() == 0) throw InputError(h.place.at(h.atoms_line) + "expected atoms, got none");
  refuse_a_2d_run(f, h.box.container, h.place.at(h.box.line));
  f.step = *h.place.timestep;
  f.time = h.time ? *h.time : dt_ > 0 ? dt_ * static_cast<double>(f.step) : std::nan("");
  if (!h.time && dt_ > 0 && !std::isfinite(f.time)) {
    throw InputError(dt_param_ + ": expected a time step whose product with the dump's TIMESTEP " +
                     std::to_string(f.step) + " is finite, got " + format_number(dt_));
  }
  check_times_stated_alike(h);
  f.container = stated_.place(h.box.container, h.place.where(h.box.line));
  const std::string box = "the dump's BOX BOUNDS, line " + std::to_string(h.box.line);
  if (const auto out = stated_.first_outside(f, h.box.container, box)) {
    throw InputError(h.place.at(atoms.lines[static_cast<std::size_t>(out->particle)]) +
                     out->message);
  }
  refuse_deep_overlap(f, max_overlap_, max_overlap_param_, "", h.place.where(h.place.first_line));
  add_contacts(f, atoms.precision);
  precision_ = atoms.precision;
  f.check(h.place.where(h.place.first_line));
  check_time_follows(f, h);
  return std::move(f);
}

// A dump states ITEM: TIME in every snapshot or in none (dump_modify time): snapshots of
// two dumps joined had their times from the file and from dt x TIMESTEP mixed, exit 0.
void LammpsDumpSource::check_times_stated_alike(const SnapshotHeader& h) {
  if (!times_stated_) times_stated_ = h.time.has_value();
  if (*times_stated_ == h.time.has_value()) return;
  throw InputError(h.place.at(h.place.first_line) + "expected " +
                   (*times_stated_ ? "ITEM: TIME, as" : "no ITEM: TIME, as none of") +
                   " the snapshots read before it, got " + (*times_stated_ ? "none" : "one"));
}

// Snapshots come in rising timesteps (the index checks them); their ITEM: TIME values follow
// (a dump whose times ran down gave the intruder's lift-offs backwards, exit 0). An undefined
// time (NaN) is compared with nothing.
void LammpsDumpSource::check_time_follows(const Frame& f, const SnapshotHeader& h) {
  if (time_order_.runs_back(f.time)) {
    throw InputError(h.place.at(h.place.first_line) + "expected a time at or after " +
                     format_number(time_order_.last()) + " (the snapshot read before it), got " +
                     format_number(f.time));
  }
  time_order_.pass(f.time);
}

bool LammpsDumpSource::next(Frame& frame) {
  if (next_ > selection_.last) return false;
  if (first_frame_) {
    frame = std::move(*first_frame_);
    first_frame_.reset();
  } else {
    frame = read_snapshot(next_);
  }
  next_ += selection_.stride;
  ++read_;
  return true;
}

void LammpsDumpSource::finish(Results& results) {
  results.add_scalar("frames_read", static_cast<double>(read_), std::nan(""), "",
                     "snapshots read from " + file_);
}

}  // namespace granpipe::lammps_dump
