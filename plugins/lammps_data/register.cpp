#include "lammps_data_source.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_source<granpipe::lammps_data::LammpsDataSource>(
      "lammps_data", "one frame from a LAMMPS data file of spheres, in a given container",
      granpipe::lammps_data::schema());
}
