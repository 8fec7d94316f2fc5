// A LAMMPS data file of spheres read back: ids in order, radii, species, positions; other
// atom styles, malformed lines, wrong atom counts, repeated ids and particles outside the
// given container refused with the line or atom named.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "data_file.hpp"
#include "lammps_data_source.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

// The message read_atoms throws for this file content.
std::string refusal(const std::string& content) {
  std::istringstream in(content);
  return test::input_error_of([&] { lammps_data::read_atoms(in, "x.data"); });
}

// A data file of two spheres of radius 0.5 (atom ids 1 and 7) at these positions.
std::string two_spheres(const std::string& at1, const std::string& at7) {
  return "LAMMPS data file via write_data\n\n2 atoms\n1 atom types\n\n-2 2 xlo xhi\n-2 2 ylo "
         "yhi\n0 10 zlo zhi\n\nAtoms # sphere\n\n"
         "1 1 1 1.91 " +
         at1 + " 0 0 0\n7 1 1 1.91 " + at7 + " 0 0 0\n";
}

}  // namespace

TEST(LammpsData, AtomsAreReadInIdOrderWithRadiusAndSpecies) {
  std::istringstream in(R"(LAMMPS data file via write_data

2 atoms
2 atom types

-6.3 6.3 xlo xhi
-6.3 6.3 ylo yhi
0 10 zlo zhi

Atoms # sphere

7 1 1 1.91 -2.5 1.0 0.5 0 0 0
1 2 3.16 13.54 0 0 1.6 0 0 0

Velocities

1 0 0 0 0 0 0
7 0 0 0 0 0 0
)");
  const Frame f = lammps_data::read_atoms(in, "x.data");
  ASSERT_EQ(f.size(), 2);
  EXPECT_EQ(f.id()[0], 1);
  EXPECT_EQ(f.species()[0], 1);
  EXPECT_DOUBLE_EQ(f.radius()[0], 1.58);
  EXPECT_DOUBLE_EQ(f.position()(0, 2), 1.6);
  EXPECT_EQ(f.id()[1], 7);
  EXPECT_EQ(f.species()[1], 0);
  EXPECT_DOUBLE_EQ(f.radius()[1], 0.5);
  EXPECT_DOUBLE_EQ(f.position()(1, 0), -2.5);
  EXPECT_EQ(f.container.lo, Eigen::Vector3d(-6.3, -6.3, 0));
  EXPECT_EQ(f.container.hi, Eigen::Vector3d(6.3, 6.3, 10));
  EXPECT_EQ(f.container.boundary[0][0], Boundary::Open);
}

// A file saved on Windows ends its lines with "\r\n": read as the same file, not refused for
// "atoms\r" or "sphere\r".
TEST(LammpsData, WindowsLineEndsReadAsTheSameFile) {
  std::string text = two_spheres("0 0 1", "0 0 3"), crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  std::istringstream unix_in(text), windows_in(crlf);
  const Frame unix_frame = lammps_data::read_atoms(unix_in, "x.data");
  const Frame windows_frame = lammps_data::read_atoms(windows_in, "x.data");
  EXPECT_EQ(windows_frame.size(), 2);
  EXPECT_TRUE((windows_frame.position() == unix_frame.position()).all());
  EXPECT_EQ(windows_frame.container.hi, unix_frame.container.hi);
}

// The box was not read: the source invented x and y sides about the atoms (walls at +-4 for
// a simple cubic block in 0..4, packing fraction 0.13 for 0.52, exit 0). A box line missing,
// malformed or tilted is refused.
TEST(LammpsData, TheBoxIsReadAndRequired) {
  const std::string head = "title\n1 atoms\n";
  const std::string atoms = "\nAtoms # sphere\n\n1 1 1 1 0.5 0.5 0.5\n";
  EXPECT_EQ(refusal(head + "0 4 xlo xhi\n0 4 ylo yhi\n" + atoms),
            "x.data: expected the header line \"lo hi zlo zhi\" of the box (as write_data "
            "writes it), got none");
  EXPECT_EQ(refusal(head + "0 4 xlo xhi\n4 0 ylo yhi\n0 4 zlo zhi\n" + atoms),
            "x.data: line 4: expected \"lo hi ylo yhi\" with finite lo < hi, got \"4 0 ylo yhi\"");
  EXPECT_EQ(refusal(head + "0 nan xlo xhi\n" + atoms),
            "x.data: line 3: expected \"lo hi xlo xhi\" with finite lo < hi, got \"0 nan xlo "
            "xhi\"");
  EXPECT_EQ(refusal(head + "0 4 xlo xhi\n0 4 ylo yhi\n0 4 zlo zhi\n1 0 0 xy xz yz\n" + atoms),
            "x.data: line 6: expected an orthogonal box, got a triclinic one's tilt \"1 0 0 xy xz "
            "yz\": granpipe's containers have right angles");
}

// A second line for one axis, or a second "N atoms", was taken over the first without a
// word (a packing fraction of another box: 0.00042 for 0.0066); a file without line ends
// was read whole into memory before it was refused.
TEST(LammpsData, HeaderLinesGivenTwiceAndEndlessLinesAreRefused) {
  const std::string box = "0 4 xlo xhi\n0 4 ylo yhi\n0 4 zlo zhi\n";
  const std::string atoms = "\nAtoms # sphere\n\n1 1 1 1 0.5 0.5 0.5\n";
  EXPECT_EQ(refusal("title\n1 atoms\n" + box + "-100 100 xlo xhi\n" + atoms),
            "x.data: line 6: expected one \"lo hi xlo xhi\" line, got a second (the first on "
            "line 3)");
  EXPECT_EQ(refusal("title\n1 atoms\n" + box + "2 atoms\n" + atoms),
            "x.data: line 6: expected one \"N atoms\" line, got a second (the first on line 2)");
  EXPECT_EQ(refusal("title\n" + std::string((std::size_t{1} << 20) + 1, '0')),
            "x.data: line 2: expected a line of a LAMMPS data file, got one longer than 1048576 "
            "characters");
  // The longest line, written on Windows: its carriage return is no character of it.
  EXPECT_EQ(refusal(std::string(std::size_t{1} << 20, 't') + "\r\n1 atoms\n" + box + atoms),
            "no refusal");
}

// A NaN was named later by the atom's id alone.
TEST(LammpsData, ANanOrInfinitePositionIsNamedWithItsLine) {
  EXPECT_EQ(refusal(two_spheres("0 0 0.5", "1.5 0 nan")),
            "x.data: line 13: expected a finite diameter and position, got \"7 1 1 1.91 1.5 0 nan "
            "0 0 0\"");
  EXPECT_EQ(refusal(two_spheres("inf 0 0.5", "1.5 0 1")),
            "x.data: line 12: expected a finite diameter and position, got \"1 1 1 1.91 inf 0 0.5 "
            "0 0 0\"");
}

TEST(LammpsData, AMalformedLineIsNamed) {
  EXPECT_EQ(refusal("title\n1 atoms\n\nAtoms # sphere\n\n1 1 one 1.91 0 0 0\n"),
            "x.data: line 6: expected \"id type diameter density x y z\" (atom_style sphere), "
            "got \"1 1 one 1.91 0 0 0\"");
}

// atom_style full has sphere's 7 columns: read as sphere, the molecule id would be the type
// and the type the diameter.
TEST(LammpsData, AnotherAtomStyleIsRefusedByName) {
  EXPECT_EQ(
      refusal("title\n1 atoms\n\nAtoms # full\n\n1 3 1 -0.5 0 0 0\n"),
      "x.data: line 4: expected the Atoms section of atom_style sphere, got atom_style \"full\"");
}

// Without the style comment the columns decided, and atom_style full has sphere's 7: its
// molecule ids were read as types and its types as diameters (1, a plausible size), exit 0.
TEST(LammpsData, AnAtomsSectionThatNamesNoStyleIsRefused) {
  EXPECT_EQ(refusal("title\n1 atoms\n\nAtoms\n\n1 1 1 -0.5 0 0 0\n"),
            "x.data: line 4: expected the Atoms section to name its atom style (\"Atoms # "
            "sphere\", as write_data writes it), got \"Atoms\": atom_style full has sphere's 7 "
            "columns and would be misread");
  EXPECT_EQ(refusal("title\n1 atoms\n\nAtoms # \n\n1 1 1 -0.5 0 0 0\n"),
            "x.data: line 4: expected the Atoms section to name its atom style (\"Atoms # "
            "sphere\", as write_data writes it), got \"Atoms # \": atom_style full has sphere's "
            "7 columns and would be misread");
  EXPECT_EQ(refusal("title\n1 atoms\n-1 1 xlo xhi\n-1 1 ylo yhi\n-1 1 zlo zhi\nAtoms "
                    "#sphere\n1 1 1 1 0 0 0\n"),
            "no refusal");
}

TEST(LammpsData, TooFewAtomsNameTheSectionAndTheHeader) {
  EXPECT_EQ(
      refusal("title\n\n3 atoms\n\nAtoms # sphere\n\n1 1 1 1 0 0 0\n2 1 1 1 2 0 0\n\n"
              "Velocities\n\n1 0 0 0 0 0 0\n"),
      "x.data: line 5: expected the Atoms section to hold 3 atoms (the header's, line 3), got 2");
}

TEST(LammpsData, TooManyAtomsAreRefused) {
  EXPECT_EQ(
      refusal("title\n1 atoms\nAtoms # sphere\n1 1 1 1 0 0 0\n2 1 1 1 2 0 0\n"),
      "x.data: line 3: expected the Atoms section to hold 1 atoms (the header's, line 2), got 2");
}

TEST(LammpsData, AnAtomIdGivenTwiceIsRefusedWithBothLines) {
  EXPECT_EQ(refusal("title\n2 atoms\nAtoms # sphere\n4 1 1 1 0 0 0\n4 1 1 1 2 0 0\n"),
            "x.data: line 5: expected each atom id once, got id 4 again (first on line 4)");
}

// LAMMPS numbers atoms and types from 1: id 0 or -3 was read as an atom, "1.5" as id 1.
TEST(LammpsData, IdsAndTypesAreWholeNumbersFromOne) {
  const std::string head = "title\n1 atoms\nAtoms # sphere\n";
  for (const std::string atom : {"0 1 1 1 0 0 0", "-3 1 1 1 0 0 0", "1.5 1 1 1 0 0 0",
                                 "1 0 1 1 0 0 0", "1 4294967296 1 1 0 0 0"}) {
    EXPECT_EQ(refusal(head + atom + "\n"),
              "x.data: line 4: expected an atom id and a type, whole numbers >= 1 (up to "
              "2147483647 types), got \"" +
                  atom + "\"");
  }
}

// LAMMPS refuses a type beyond the header's "atom types"; read, it was a species of its own.
TEST(LammpsData, ATypeBeyondTheHeadersCountIsRefused) {
  const std::string head = "title\n2 atoms\n1 atom types\nAtoms # sphere\n1 1 1 1 0 0 0\n";
  EXPECT_EQ(refusal(head + "2 3 1 1 2 0 0\n"),
            "x.data: line 6: expected an atom type from 1 to 1 (the header's \"atom types\", "
            "line 3), got 3");
  EXPECT_EQ(refusal("title\n1 atoms\n0 atom types\nAtoms # sphere\n1 1 1 1 0 0 0\n"),
            "x.data: line 3: expected \"N atom types\" with N a whole number >= 1, got \"0 atom "
            "types\"");
}

// Two data files joined: the atoms of the second Atoms section were left out, exit 0.
TEST(LammpsData, ASecondAtomsSectionIsRefused) {
  EXPECT_EQ(refusal("title\n1 atoms\nAtoms # sphere\n1 1 1 1 0 0 0\n\nVelocities\n\n1 0 0 0 0 0 "
                    "0\n\nAtoms # sphere\n\n2 1 1 1 2 0 0\n"),
            "x.data: line 10: expected one Atoms section, got a second (the first on line 3)");
  EXPECT_EQ(refusal("title\n1 atoms\nAtoms # sphere\n1 1 1 1 0 0 0\nAtoms # sphere\n"),
            "x.data: line 5: expected one Atoms section, got a second (the first on line 3)");
}

// LAMMPS refuses a density <= 0 and reads image flags as integers: a NaN density or flags
// "a b c" were read as spheres, exit 0.
TEST(LammpsData, DensitiesAndImageFlagsAreChecked) {
  const std::string head = "title\n1 atoms\nAtoms # sphere\n";
  for (const std::string density : {"nan", "-1", "0", "inf"}) {
    EXPECT_EQ(refusal(head + "1 1 1 " + density + " 0 0 0\n"),
              "x.data: line 4: expected a finite density > 0 in column 4, got \"" + density + "\"");
  }
  for (const std::string flags : {"a b c", "0 1.5 0"}) {
    EXPECT_EQ(refusal(head + "1 1 1 1 0 0 0 " + flags + "\n"),
              "x.data: line 4: expected whole-number image flags in columns 8 to 10, got \"1 1 1 "
              "1 0 0 0 " +
                  flags + "\"");
  }
  // An atom that crossed a periodic side: the run was periodic along y, and its sides, read
  // as open, lost the pairs across it (a packing fraction of 0.458 for 0.485, exit 0).
  EXPECT_EQ(refusal(head + "1 1 1 1 0 0 0 0 -1 0\n"),
            "x.data: line 4: expected image flags 0 (a data file's sides are read as open), got -1 "
            "along y in \"1 1 1 1 0 0 0 0 -1 0\": the run was periodic along y; read its dump with "
            "the lammps_dump source, which reads periodic sides");
}

// A dump's first line would pass for a title: the dump is named as such.
TEST(LammpsData, ADumpIsNamedWithTheSourceThatReadsIt) {
  EXPECT_EQ(refusal("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\n"),
            "x.data: line 1: expected a LAMMPS data file (a title, then \"N atoms\"), got "
            "\"ITEM: TIMESTEP\": this is a LAMMPS dump, use the lammps_dump source");
}

// A binary file read as text was refused for a missing "N atoms", as if a header were
// wrong: its kind is named instead.
TEST(LammpsData, AnHdf5OrGzipFileIsNamedAsSuch) {
  EXPECT_EQ(refusal(std::string("\x89HDF\r\n\x1a\n\0\0", 10)),
            "x.data: line 1: expected a LAMMPS data file (a title, then \"N atoms\"), got an "
            "HDF5 file: use the h5md source");
  EXPECT_EQ(refusal(std::string("\x1f\x8b\x08\0\0\0", 6)),
            "x.data: line 1: expected a LAMMPS data file (a title, then \"N atoms\"), got a "
            "gzip file: decompress it first");
}

class LammpsDataSource : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("granpipe_lammps_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The source's refusal of this file in a cylinder of radius 2 on a base at z = 0, or
  // "accepted".
  std::string refusal(const std::string& content, double top = 100.0) {
    const fs::path file = dir_ / "spheres.data";
    std::ofstream(file) << content;
    harness_ = test::make_context(
        "lammps_data",
        {{"file", file.string()}, {"cylinder_radius", 2.0}, {"base", 0.0}, {"top", top}});
    try {
      lammps_data::LammpsDataSource source(*harness_);
      EXPECT_EQ(source.work().total, 1.0);  // one frame, announced as such
    } catch (const InputError& e) {
      const std::string m = e.what();
      return m.substr(m.find("spheres.data"));
    }
    return "accepted";
  }

  fs::path dir_;
  std::unique_ptr<test::PluginHarness> harness_;
};

TEST_F(LammpsDataSource, SpheresInsideOrTouchingTheWallsAreAccepted) {
  EXPECT_EQ(refusal(two_spheres("0 0 0.5", "1.5 0 0.52")), "accepted");
  // Pressed into the cylinder and the base by 4 % of the radius: a soft contact.
  EXPECT_EQ(refusal(two_spheres("0 0 0.48", "1.52 0 2")), "accepted");
}

// A diameter of 1e-320 gave a sphere of volume 0, a centre at 1e300 squared distances of
// infinity: sizes and places a double cannot compute with are refused.
TEST_F(LammpsDataSource, AbsurdSizesAndPlacesAreRefused) {
  const std::string head =
      "title\n\n2 atoms\n\n-2 2 xlo xhi\n-2 2 ylo yhi\n0 10 zlo zhi\n\n"
      "Atoms # sphere\n\n1 1 1 1.91 0 0 0.5\n";
  EXPECT_EQ(refusal(head + "7 1 1e-320 1.91 1 1 1\n"),
            "spheres.data: particle 1 (id 7): expected a radius from 1e-100 to 1e+100, got "
            "4.99994e-321");
  EXPECT_EQ(refusal(head + "7 1 1 1.91 1 1 1e300\n", 1e301),
            "spheres.data: particle 1 (id 7): expected a position within +-1e+100, got 1e+300 in "
            "coordinate z");
}

// write_data of a 2D run: disks at z = 0 in a box one atom thick, read as spheres (exit 0).
TEST_F(LammpsDataSource, AFlatLayerOfA2dRunIsRefusedAsSuch) {
  const std::string flat =
      "title\n\n2 atoms\n\n-2 2 xlo xhi\n-2 2 ylo yhi\n-0.5 0.5 zlo zhi\n\n"
      "Atoms # sphere\n\n1 1 1 1.91 0 0 0\n7 1 1 1.91 1 0 0\n";
  EXPECT_EQ(refusal(flat),
            "spheres.data: expected a 3D packing (granpipe's LAMMPS readers read 3D runs), got "
            "every atom at z = 0 in a box from zlo -0.5 to zhi 0.5: a 2D run's data file (a 3D "
            "packing in the plane z = 0 cannot be told from one: shift its atoms and box off z = "
            "0 to have it read)");
  // Small disks in LAMMPS' usual 2D box, -0.5 to 0.5, likewise.
  EXPECT_NE(refusal("title\n\n2 atoms\n\n-2 2 xlo xhi\n-2 2 ylo yhi\n-0.5 0.5 zlo zhi\n\n"
                    "Atoms # sphere\n\n1 1 0.2 1.91 0 0 0\n7 1 0.2 1.91 1 0 0\n")
                .find("a 2D run's data file"),
            std::string::npos);
  // A 3D monolayer on a base, in a box one diameter thick, is no 2D run.
  EXPECT_EQ(refusal("title\n\n2 atoms\n\n-2 2 xlo xhi\n-2 2 ylo yhi\n0 1 zlo zhi\n\n"
                    "Atoms # sphere\n\n1 1 1 1.91 0 0 0.5\n7 1 1 1.91 1 0 0.5\n"),
            "accepted");
}

TEST_F(LammpsDataSource, ASphereThroughTheCylinderIsRefusedByAtomId) {
  EXPECT_EQ(refusal(two_spheres("0 0 0.5", "1.9 0 1")),
            "spheres.data: atom 7 at (1.9, 0, 1), radius 0.5: expected an overlap with the wall "
            "cylinder (radius 2 about (0, 0)) of at most 0.025 (0.05 of its radius), got 0.4 (the "
            "container of params.cylinder_radius)");
}

// The container's parameters are the lammps_dump source's (granpipe/stated_container.hpp).
TEST_F(LammpsDataSource, TheCylinderAxisAndSideWallsPlaceTheWalls) {
  std::ofstream(dir_ / "spheres.data") << two_spheres("0 0 0.5", "1.9 0 1");
  harness_ = test::make_context("lammps_data", {{"file", (dir_ / "spheres.data").string()},
                                                {"cylinder_radius", 2.0},
                                                {"cylinder_axis", {0.5, 0}}});
  Frame f;
  ASSERT_TRUE(lammps_data::LammpsDataSource(*harness_).next(f));
  EXPECT_EQ(f.container.cylinder_center, Eigen::Vector2d(0.5, 0));
  EXPECT_EQ(f.container.lo[0], -1.5);
  EXPECT_EQ(f.container.hi[1], 2.0);
  harness_ = test::make_context("lammps_data", {{"file", (dir_ / "spheres.data").string()},
                                                {"side_walls", {-1, 2.4, -1, 1}}});
  ASSERT_TRUE(lammps_data::LammpsDataSource(*harness_).next(f));
  EXPECT_EQ(f.container.shape, ContainerShape::Box);
  EXPECT_EQ(f.container.hi[0], 2.4);
  EXPECT_EQ(f.container.boundary[0][1], Boundary::Wall);
}

// Without stated side walls or a cylinder the x and y sides are the box's, open: a block
// of spheres fills it, and a centre beyond it is refused.
TEST_F(LammpsDataSource, WithoutStatedSidesTheBoxHoldsTheAtoms) {
  const fs::path file = dir_ / "spheres.data";
  std::ofstream(file) << two_spheres("0 0 0.5", "1.5 -1.5 0.5");
  harness_ = test::make_context("lammps_data", {{"file", file.string()}});
  Frame f;
  ASSERT_TRUE(lammps_data::LammpsDataSource(*harness_).next(f));
  EXPECT_EQ(f.container.lo, Eigen::Vector3d(-2, -2, 0));
  EXPECT_EQ(f.container.hi[0], 2.0);
  EXPECT_EQ(f.container.boundary[0][1], Boundary::Open);
  EXPECT_EQ(f.container.boundary[2][0], Boundary::Wall);  // the stated base
  std::ofstream(file) << two_spheres("0 0 0.5", "2.5 0 0.5");
  harness_ = test::make_context("lammps_data", {{"file", file.string()}});
  EXPECT_EQ(test::input_error_of([&] { lammps_data::LammpsDataSource source(*harness_); }),
            file.string() +
                ": atom 7 at (2.5, 0, 0.5), radius 0.5: expected its centre inside the "
                "open side x_high (x = 2), got it 0.5 beyond (the data file's box)");
}

TEST_F(LammpsDataSource, ASphereBelowTheBaseOrAboveTheTopIsRefused) {
  EXPECT_EQ(refusal(two_spheres("0 0 0.4", "1 0 3")),
            "spheres.data: atom 1 at (0, 0, 0.4), radius 0.5: expected an overlap with the wall "
            "z_low (z = 0) of at most 0.025 (0.05 of its radius), got 0.1 (the container of "
            "params.base)");
  EXPECT_EQ(refusal(two_spheres("0 0 0.5", "1 0 3"), 2.0),
            "spheres.data: atom 7 at (1, 0, 3), radius 0.5: expected its centre inside the open "
            "side z_high (z = 2), got it 1 beyond (the container of params.top)");
}

// Atom 3 on atom 1 was read as two spheres (the packing fraction counting their volume
// twice), exit 0.
TEST_F(LammpsDataSource, AtomsOverlappingBeyondMaxOverlapAreRefused) {
  EXPECT_EQ(refusal(two_spheres("0 0 1", "0 0 1.8")),
            "spheres.data: particles 1 and 7 overlap by 0.4 of the smaller radius, expected at "
            "most 0.3 (params.max_overlap)");
  EXPECT_EQ(refusal(two_spheres("0 0 1", "0 0 1.9")), "accepted");  // 0.2: a soft contact
}
