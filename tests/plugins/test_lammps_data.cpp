// A LAMMPS data file of spheres read back: ids in order, radii, species, positions; bad lines
// named.
#include <gtest/gtest.h>

#include <sstream>

#include "lammps_data_source.hpp"

using namespace granpipe;

TEST(LammpsData, AtomsAreReadInIdOrderWithRadiusAndSpecies) {
  std::istringstream in(R"(LAMMPS data file via write_data

2 atoms
2 atom types

-6.3 6.3 xlo xhi

Atoms # sphere

7 1 1 1.91 -2.5 1.0 0.5 0 0 0
1 2 3.16 13.54 0 0 1.6 0 0 0
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
}

TEST(LammpsData, AMalformedLineIsNamed) {
  std::istringstream in("1 atoms\n\nAtoms\n\n1 1 one 1.91 0 0 0\n");
  try {
    lammps_data::read_atoms(in, "x.data");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "x.data: line 5: expected \"id type diameter density x y z\" "
                           "(atom_style sphere), got \"1 1 one 1.91 0 0 0\"");
  }
}
