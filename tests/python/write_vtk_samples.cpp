// Writes the vtk writer's two sample frames (tests/plugins/vtk_sample_frames.hpp) into the
// directory given, as a run would: test_000000.vtp, test_000001.vtp and test.pvd, for the
// readers of tests/vtk_xml_check.py and tests/vtk_reader_check.py.
#include <filesystem>
#include <iostream>

#include "plugin_harness.hpp"
#include "vtk_sample_frames.hpp"
#include "vtk_writer.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_vtk_samples DIR\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  const auto ctx = granpipe::test::make_context(granpipe::Schema{}, {}, 1, dir);
  granpipe::vtk::VtkWriter writer(ctx->context());
  writer.write(granpipe::test::vtk_sample_frame());
  writer.write(granpipe::test::vtk_sample_frame_later());
  writer.close();
  return 0;
}
