#pragma once
// Where a snapshot of a dump is, for messages and for a file that ends inside it.
#include <cstdint>
#include <optional>
#include <string>

#include "text_lines.hpp"

namespace granpipe::lammps_dump {

struct SnapshotPlace {
  std::string file;
  long first_line = 0;                     // its first "ITEM:" line
  std::optional<std::int64_t> timestep{};  // once read

  // "x.dump: timestep 100, line 7": one of its lines, for a message.
  std::string where(long line) const;
  // The start of a one-line message about one of its lines: "x.dump: timestep 100, line 7: ".
  std::string at(long line) const { return where(line) + ": "; }
  // "the snapshot of timestep 100 (from line 1)", or of line 1 when its timestep is unread.
  std::string name() const;
};

// Thrown when the file ends inside a snapshot (its writer was stopped): the snapshots
// before it are complete (dump_index.hpp).
struct SnapshotCut {
  SnapshotPlace place;
};

// The snapshot's next line; SnapshotCut when the file ends before it or inside it.
void next_line_of(const SnapshotPlace& place, TextLines& lines, std::string& line);

}  // namespace granpipe::lammps_dump
