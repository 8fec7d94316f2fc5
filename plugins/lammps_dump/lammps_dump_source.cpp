#include "lammps_dump_source.hpp"

#include <cmath>

#include "granpipe/format_number.hpp"
#include "snapshot_atoms.hpp"

namespace granpipe::lammps_dump {

namespace {

DumpIndex complete_snapshots(TextLines& lines) {
  DumpIndex index = index_snapshots(lines);
  if (index.snapshots.empty()) {
    throw InputError(lines.path() +
                     ": expected a complete snapshot, got none: the file ends "
                     "inside " +
                     index.cut->name());
  }
  return index;
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
  return s;
}

LammpsDumpSource::LammpsDumpSource(const PluginContext& ctx)
    : file_(ctx.params.string("file")),
      stated_(ctx),
      radius_(ctx.params.real("radius")),
      dt_(ctx.params.real("dt")),
      lines_(file_),
      index_(complete_snapshots(lines_)),
      columns_(parse_atom_columns(index_.columns, index_.columns_at)) {
  const long snapshots = static_cast<long>(index_.snapshots.size());
  warn_if_cut(ctx);
  check_radius(ctx);
  selection_ = select_frames(ctx, snapshots,
                             " (" + file_ + " holds " + std::to_string(snapshots) + " snapshots)");
  next_ = selection_.first;
  first_frame_ = read_snapshot(selection_.first);
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
  f.step = *h.place.timestep;
  f.time = h.time ? *h.time : dt_ > 0 ? dt_ * static_cast<double>(f.step) : std::nan("");
  f.container = stated_.place(h.box.container, h.place.where(h.box.line));
  const std::string box = "the dump's BOX BOUNDS, line " + std::to_string(h.box.line);
  if (const auto out = stated_.first_outside(f, box)) {
    throw InputError(h.place.at(atoms.lines[static_cast<std::size_t>(out->particle)]) +
                     out->message);
  }
  f.check(h.place.where(h.place.first_line));
  return std::move(f);
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
