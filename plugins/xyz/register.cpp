#include "xyz_writer.hpp"

namespace {

granpipe::Schema schema() {
  granpipe::Schema s;
  s.integer("digits", 17, "significant digits of real values (17: exact round trip)").range(3, 17);
  return s;
}

}  // namespace

GRANPIPE_PLUGIN(registry) {
  registry.add_writer<granpipe::xyz::XyzWriter>(
      "xyz", "frames as extended XYZ (OVITO, ASE), every particle column", schema());
}
