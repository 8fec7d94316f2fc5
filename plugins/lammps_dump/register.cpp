#include "lammps_dump_source.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_source<granpipe::lammps_dump::LammpsDumpSource>(
      "lammps_dump", "frames from a LAMMPS or LIGGGHTS text dump, in a given container",
      granpipe::lammps_dump::schema());
}
