// The vtk writer: the PolyData of a tiny frame (counts, cells, arrays to the byte, base64
// worked out by Python's base64 and struct), the collection's timesteps, and a pipeline
// whose run directory holds one .vtp per frame and the .pvd listing them.
// tests/plugins/vtk_check_xml.py and vtk_check_reader.py read the same frames back.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "granpipe/pipeline.hpp"
#include "granpipe/plugin_loader.hpp"
#include "granpipe/version.hpp"
#include "vtk_collection.hpp"
#include "vtk_polydata.hpp"
#include "vtk_sample_frames.hpp"
#include "vtk_writer.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(Vtk, ParticlesAreVerticesAndParticleContactsLines) {
  const std::string xml = vtk::polydata_xml(test::vtk_sample_frame());
  EXPECT_TRUE(contains(xml,
                       "<Piece NumberOfPoints=\"3\" NumberOfVerts=\"3\" NumberOfLines=\"1\" "
                       "NumberOfStrips=\"0\" NumberOfPolys=\"0\">"));
  EXPECT_TRUE(contains(xml,
                       "      <Verts>\n"
                       "        <DataArray type=\"Int64\" Name=\"connectivity\" "
                       "format=\"ascii\">0 1 2</DataArray>\n"
                       "        <DataArray type=\"Int64\" Name=\"offsets\" "
                       "format=\"ascii\">1 2 3</DataArray>\n"
                       "      </Verts>\n"
                       "      <Lines>\n"
                       "        <DataArray type=\"Int64\" Name=\"connectivity\" "
                       "format=\"ascii\">0 1</DataArray>\n"
                       "        <DataArray type=\"Int64\" Name=\"offsets\" "
                       "format=\"ascii\">2</DataArray>\n"
                       "      </Lines>\n"));
}

TEST(Vtk, EveryParticleColumnIsPointDataWithItsTypeAndComponents) {
  const std::string xml = vtk::polydata_xml(test::vtk_sample_frame());
  EXPECT_TRUE(
      contains(xml,
               "<DataArray type=\"Float64\" Name=\"radius\" NumberOfComponents=\"1\" "
               "format=\"binary\">GAAAAAAAAAAAAAAAAADgPwAAAAAAAOA/AAAAAAAA0D8=</DataArray>"));
  EXPECT_TRUE(contains(xml,
                       "<DataArray type=\"Int32\" Name=\"species\" NumberOfComponents=\"1\" "
                       "format=\"binary\">DAAAAAAAAAAAAAAAAAAAAAEAAAA=</DataArray>"));
  EXPECT_TRUE(
      contains(xml,
               "<DataArray type=\"Int64\" Name=\"network\" NumberOfComponents=\"1\" "
               "format=\"binary\">GAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA//////////8=</DataArray>"));
  EXPECT_TRUE(contains(xml, "Name=\"velocity\" NumberOfComponents=\"3\""));
  EXPECT_TRUE(contains(xml, "Name=\"voronoi_volume\" NumberOfComponents=\"1\""));
  EXPECT_TRUE(contains(xml, "Name=\"id\" NumberOfComponents=\"1\""));
  EXPECT_EQ(xml.find("Name=\"position\""), xml.rfind("Name=\"position\""));  // the points only
}

TEST(Vtk, ContactColumnsAreCellDataWithNoValueOnTheVertexCells) {
  const std::string xml = vtk::polydata_xml(test::vtk_sample_frame());
  // Three vertex cells (-1), then the one line: the wall contact is left out.
  EXPECT_TRUE(contains(xml,
                       "<DataArray type=\"Int64\" Name=\"mst_pass\" NumberOfComponents=\"1\" "
                       "format=\"binary\">IAAAAAAAAAD///////////////////////////////8BAAAAAAAAAA=="
                       "</DataArray>"));
  EXPECT_TRUE(contains(xml, "Name=\"normal_force\" NumberOfComponents=\"3\""));
  EXPECT_FALSE(contains(xml, "Name=\"i\""));
  EXPECT_FALSE(contains(xml, "Name=\"j\""));
}

TEST(Vtk, TwoDimensionalPointsGetZEqualZero) {
  Frame f;
  f.resize(2, 2);
  f.position() << 0.5, 1.0, 2.25, 1.0;
  const std::string xml = vtk::polydata_xml(f);
  EXPECT_TRUE(contains(xml,
                       "      <Points>\n"
                       "        <DataArray type=\"Float64\" Name=\"position\" "
                       "NumberOfComponents=\"3\" format=\"binary\">MAAAAAAAAAAAAAAAAADgPwAAAAAAAPA/"
                       "AAAAAAAAAAAAAAAAAAACQAAAAAAAAPA/AAAAAAAAAAA=</DataArray>\n"
                       "      </Points>\n"));
  EXPECT_TRUE(contains(xml, "NumberOfLines=\"0\""));
}

TEST(Vtk, TimestepsAreTimesThenStepsThenIndices) {
  using W = vtk::WrittenFrame;
  EXPECT_EQ(vtk::timesteps({W{0.5, 7, "a"}, W{0.75, 7, "b"}}), (std::vector<double>{0.5, 0.75}));
  EXPECT_EQ(vtk::timesteps({W{0, 100, "a"}, W{0, 150, "b"}}), (std::vector<double>{100, 150}));
  EXPECT_EQ(vtk::timesteps({W{0, 3, "a"}, W{0, 3, "b"}}), (std::vector<double>{0, 1}));
  // An undefined time (a dump read without dt) is no timestep, even of a single frame.
  const double nan = std::nan("");
  EXPECT_EQ(vtk::timesteps({W{nan, 40, "a"}}), (std::vector<double>{40}));
  EXPECT_EQ(vtk::timesteps({W{nan, 40, "a"}, W{nan, 80, "b"}}), (std::vector<double>{40, 80}));
}

TEST(Vtk, CollectionListsEveryFrameWithItsTimestep) {
  EXPECT_EQ(vtk::collection_xml({{0.5, 100, "movie_000000.vtp"}, {0.75, 150, "movie_000001.vtp"}}),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0.5\" part=\"0\" file=\"movie_000000.vtp\"/>\n"
            "    <DataSet timestep=\"0.75\" part=\"0\" file=\"movie_000001.vtp\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
}

TEST(Vtk, APipelineWritesOneFilePerFrameAndTheCollection) {
  Registry r;
  load_plugins(r, plugin_search_path());
  const Pipeline p = Pipeline::parse(R"({"seed": 4,
      "source": {"plugin": "lattice", "params": {"lattice": "bcc", "cells": [2, 2, 2], "jitter": 0.1,
                                                 "frames": 3}},
      "writers": [{"plugin": "vtk", "name": "movie"}]})",
                                     "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions o;
  o.progress = false;
  o.out = fs::temp_directory_path() / ("granpipe_test_vtk_" + std::to_string(::getpid()));
  p.run(o, log);

  std::ifstream in(*o.out / "movie.pvd");
  std::stringstream pvd;
  pvd << in.rdbuf();
  for (const char* file : {"movie_000000.vtp", "movie_000001.vtp", "movie_000002.vtp"}) {
    EXPECT_TRUE(fs::exists(*o.out / file)) << file;
    EXPECT_TRUE(contains(pvd.str(), std::string("file=\"") + file + "\"")) << file;
  }
  EXPECT_FALSE(fs::exists(*o.out / "movie_000003.vtp"));
  for (const auto& entry : fs::directory_iterator(*o.out)) {
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
  }
  std::ifstream first(*o.out / "movie_000000.vtp");
  std::stringstream vtp;
  vtp << first.rdbuf();
  EXPECT_TRUE(contains(vtp.str(),
                       "<Piece NumberOfPoints=\"16\" NumberOfVerts=\"16\" "
                       "NumberOfLines=\"0\""));
  // Every file names the run that wrote it, as result files do.
  const std::string run = std::string("<?xml version=\"1.0\"?>\n<!-- granpipe ") + version() +
                          " commit " + git_commit() + " pipeline p seed 4 -->\n<VTKFile ";
  EXPECT_EQ(vtp.str().rfind(run, 0), 0u);
  EXPECT_EQ(pvd.str().rfind(run, 0), 0u);
  fs::remove_all(*o.out);
}

// A comment may not hold "--": a pipeline named a--b would have made the files malformed.
TEST(Vtk, TheRunsCommentHoldsNoDoubleDash) {
  EXPECT_EQ(vtk::with_provenance("<?xml version=\"1.0\"?>\n<VTKFile/>\n", "pipeline a--b---c"),
            "<?xml version=\"1.0\"?>\n<!-- pipeline a- -b- - -c -->\n<VTKFile/>\n");
}
