#pragma once
// A snapshot's simulation box: "ITEM: BOX BOUNDS pp pp ff" and one "lo hi" line per axis.
// Its periodic flags make periodic sides; its other sides are open (f, s and m say how
// LAMMPS moved the bounds, not where walls are: the user states the walls,
// granpipe/stated_container.hpp). A triclinic box ("xy xz yz" after BOX BOUNDS, a tilt
// after each "lo hi") is refused: granpipe's containers have right angles.
#include <string>

#include "granpipe/container.hpp"
#include "snapshot_place.hpp"
#include "text_lines.hpp"

namespace granpipe::lammps_dump {

struct DumpBox {
  Container container;
  long line = 0;  // of "ITEM: BOX BOUNDS"
};

// `item` is the "ITEM: BOX BOUNDS ..." line just read; reads the three lines after it.
DumpBox read_box(const std::string& item, const SnapshotPlace& place, TextLines& lines);

}  // namespace granpipe::lammps_dump
