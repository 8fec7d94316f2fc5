#pragma once
// `lammps_dump`: frames from a LAMMPS or LIGGGHTS text dump (`dump custom`, `dump atom`;
// plain or gzip-compressed), one per snapshot, step = its TIMESTEP, selected by first,
// last and stride as the h5md source selects frames. A dump records the box but no walls,
// so the container is stated in the pipeline (granpipe/stated_container.hpp), its periodic
// sides taken from each snapshot's BOX BOUNDS; an atom outside it is refused with its
// line. A file that ends inside a snapshot (its writer stopped) gives the complete
// snapshots before it, with a warning. Contacts with their forces come from dumps local of
// the same run (pair_file, wall_file; contact_dump.hpp); without them, a warning says when
// the positions are printed too coarsely for contacts found from them.
#include <memory>
#include <optional>
#include <string>

#include "atom_columns.hpp"
#include "contact_dump.hpp"
#include "dump_index.hpp"
#include "granpipe/frame_selection.hpp"
#include "granpipe/plugin.hpp"
#include "granpipe/stated_container.hpp"
#include "granpipe/time_order.hpp"
#include "position_precision.hpp"
#include "snapshot_header.hpp"
#include "text_lines.hpp"

namespace granpipe::lammps_dump {

Schema schema();

class LammpsDumpSource : public Source {
 public:
  explicit LammpsDumpSource(const PluginContext& ctx);

  FrameContent content() const override;
  Work work() const override { return {static_cast<double>(selection_.count()), "frames", false}; }
  bool next(Frame& frame) override;
  void finish(Results& results) override;

 private:
  void warn_if_cut(const PluginContext& ctx) const;
  void check_radius(const PluginContext& ctx) const;
  void open_contact_dumps(const PluginContext& ctx);
  // Without a pair dump, warns when the first frame's positions are printed too coarsely
  // for contacts found from them.
  void warn_if_coarse(const PluginContext& ctx, const Frame& first) const;
  // The contacts of the frame's timestep from the pair and wall dumps, when given;
  // `precision` is that of the frame's positions.
  void add_contacts(Frame& f, const PositionPrecision& precision);
  // How far off a centre distance of `f` may be, its positions being printed so.
  double distance_rounding(const PositionPrecision& precision, const Frame& f) const;
  // Whether the contact dumps give the tangential force (every one of them must).
  bool tangential() const;
  Frame read_snapshot(long index);
  // The frame of the snapshot whose header was just read: its atoms, step, time and
  // container, every atom checked to be inside.
  Frame frame_of(const SnapshotHeader& header);
  void check_time_follows(const Frame& f, const SnapshotHeader& header);
  void check_times_stated_alike(const SnapshotHeader& header);

  std::string file_;
  StatedContainer stated_;
  double radius_;  // every atom's when the dump has no radius or diameter column; else 0
  double dt_;      // the run's timestep, for the time of dumps without ITEM: TIME; else 0
  std::string dt_param_;
  std::optional<bool> times_stated_;  // whether the snapshots give ITEM: TIME, once one is read
  double max_overlap_;                // of two atoms, over the smaller radius
  std::string max_overlap_param_;
  TextLines lines_;
  DumpIndex index_;
  AtomColumns columns_;
  std::unique_ptr<ContactDump> pairs_, walls_;  // none without pair_file, wall_file
  PositionPrecision precision_;                 // of the snapshot read last
  FrameSelection selection_;
  long next_ = 0, read_ = 0;
  // Read when the source is made, so that bad atoms stop the pipeline before it runs.
  std::optional<Frame> first_frame_;
  // The last defined time read (NaN: none yet).
  TimeOrder time_order_;
};

}  // namespace granpipe::lammps_dump
