#pragma once
// Where each complete snapshot of a dump starts, found in one pass over the file before
// any frame is made: the number of frames for the selection and the progress bar, every
// header checked (a bad one stops the pipeline before it runs), and the snapshot the file
// ends inside, when its writer was stopped.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "snapshot_header.hpp"
#include "snapshot_place.hpp"
#include "text_lines.hpp"

namespace granpipe::lammps_dump {

struct SnapshotStart {
  std::int64_t offset = 0;  // of its first line, for TextLines::seek
  long line_before = 0;
  std::int64_t timestep = 0;
};

struct DumpIndex {
  std::vector<SnapshotStart> snapshots;  // the complete ones
  std::vector<std::string> columns;      // of "ITEM: ATOMS" (ENTRIES), the same in every snapshot
  std::string columns_at;                // "x.dump: timestep 0, line 9: ", where the first
                                         // snapshot names them, for messages
  std::optional<SnapshotPlace> cut;      // the snapshot the file ends inside
  bool ended_early = false;              // the gzip data stop before their end
};

// Reads `lines` to the end. InputError for a file that is not a dump (saying what it looks
// like), a header that is not a dump's, columns other than the first snapshot's, and atom
// lines more or fewer than NUMBER OF ATOMS.
DumpIndex index_snapshots(TextLines& lines, const DumpKind& kind = kAtomDump);

// index_snapshots, and InputError when the file holds no complete snapshot.
DumpIndex complete_snapshots(TextLines& lines, const DumpKind& kind = kAtomDump);

}  // namespace granpipe::lammps_dump
