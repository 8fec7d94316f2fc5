#include "vtk_writer.hpp"

GRANPIPE_PLUGIN(registry) {
  registry.add_writer<granpipe::vtk::VtkWriter>(
      "vtk",
      "frames as VTK PolyData (.vtp) and a .pvd series (ParaView, OVITO): particles with every "
      "column, contacts as lines",
      granpipe::Schema{});
}
