#include "snapshot_place.hpp"

namespace granpipe::lammps_dump {

std::string SnapshotPlace::where(long line) const {
  const std::string step = timestep ? "timestep " + std::to_string(*timestep) + ", " : "";
  return file + ": " + step + "line " + std::to_string(line);
}

std::string SnapshotPlace::name() const {
  const std::string from = "line " + std::to_string(first_line);
  if (!timestep) return "the snapshot from " + from;
  return "the snapshot of timestep " + std::to_string(*timestep) + " (from " + from + ")";
}

void next_line_of(const SnapshotPlace& place, TextLines& lines, std::string& line) {
  if (!lines.next(line) || lines.cut()) throw SnapshotCut{place};
}

}  // namespace granpipe::lammps_dump
