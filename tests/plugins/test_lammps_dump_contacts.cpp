// The lammps_dump source's contacts: dumps local of pair and wall contacts joined to the
// atom snapshots by TIMESTEP (LIGGGHTS pair/gran/local and wall/gran/local, LAMMPS
// property/local + pair/local), checked on the committed samples against a direct parse of
// their text; every refusal as one line naming the file, the timestep and the line; and the
// warning that positions printed with %g cannot resolve contacts found from them.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "lammps_dump_source.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

// Two snapshots of four atoms (ids 1, 2, 3, 10) along x in a box periodic in x and y; 1
// and 2 touch, 3 and 10 touch, 10 rests on the base z = 0.
std::string atom_snapshot(int step) {
  return "ITEM: TIMESTEP\n" + std::to_string(step) +
         "\nITEM: NUMBER OF ATOMS\n4\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 10\n"
         "ITEM: ATOMS id type x y z radius\n"
         "3 1 5 5 0.5 0.5\n1 1 1 5 2 0.5\n2 1 2 5 2 0.5\n10 1 6 5 0.5 0.5\n";
}

// LIGGGHTS `compute pair/gran/local id force_normal delta` (3 + 3 + 1 columns): the ids,
// a periodic flag, the normal force on the first atom, the overlap.
std::string pair_snapshot(int step, const std::string& entries, int count) {
  return "ITEM: TIMESTEP\n" + std::to_string(step) + "\nITEM: NUMBER OF ENTRIES\n" +
         std::to_string(count) +
         "\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 10\n"
         "ITEM: ENTRIES c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6] c_p[7] \n" +
         entries;
}

const std::string kPairs0 = "1 2 0 -1.5 0 0 0.001\n10 3 0 2.5 0 0 0.002\n";

// The atoms of atom_snapshot at steps 0 and 100 printed to 7 digits, as %g would not: their
// positions known to 1e-6 (as whole numbers, a line's direction is unknown).
std::string precise_atoms() {
  std::string atoms;
  for (const int step : {0, 100}) {
    atoms += "ITEM: TIMESTEP\n" + std::to_string(step) +
             "\nITEM: NUMBER OF ATOMS\n4\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 10\n"
             "ITEM: ATOMS id type x y z radius\n3 1 5.000000 5.000000 0.5000000 0.5\n"
             "1 1 1.000000 5.000000 2.000000 0.5\n2 1 2.000000 5.000000 2.000000 0.5\n"
             "10 1 6.000000 5.000000 0.5000000 0.5\n";
  }
  return atoms;
}

class LammpsDumpContacts : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("granpipe_dump_contacts_" + std::to_string(getpid()) + "_" + t->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& content, const std::string& name) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  // (With the run's timestep: the frames have times, and the log no word about them.)
  nlohmann::json with_pairs(const std::string& pairs) {
    return {{"file", write(atom_snapshot(0) + atom_snapshot(100), "atoms.dump")},
            {"pair_file", write(pairs, "pairs.dump")},
            {"pair_columns", "id force_normal delta"},
            {"dt", 0.001}};
  }
  std::vector<Frame> frames(const nlohmann::json& params) {
    harness_ = test::make_context("lammps_dump", params);
    harness_->keep_log();
    lammps_dump::LammpsDumpSource s(*harness_);
    std::vector<Frame> out;
    for (Frame f; s.next(f);) out.push_back(f);
    return out;
  }
  std::string refusal(const nlohmann::json& params) {
    try {
      frames(params);
    } catch (const InputError& e) {
      std::string m = e.what();
      for (auto at = m.find(dir_.string() + "/"); at != std::string::npos;
           at = m.find(dir_.string() + "/"))
        m.erase(at, dir_.string().size() + 1);
      return m;
    }
    return "accepted";
  }

  fs::path dir_;
  std::unique_ptr<test::PluginHarness> harness_;
};

}  // namespace

TEST_F(LammpsDumpContacts, PairEntriesBecomeContactRowsOfTheirTimestep) {
  const auto f = frames(
      with_pairs(pair_snapshot(0, kPairs0, 2) + pair_snapshot(100, "2 1 0 1.5 0 0 0.001\n", 1)));
  ASSERT_EQ(f.size(), 2u);
  ASSERT_TRUE(f[0].contacts);
  // Rows in id order: 1, 2, 3, 10 are rows 0 to 3.
  EXPECT_EQ(f[0].contacts->rows(), 2);
  EXPECT_EQ(f[0].contact_i()[0], 0);
  EXPECT_EQ(f[0].contact_j()[0], 1);
  EXPECT_EQ(f[0].contact_i()[1], 3);
  EXPECT_EQ(f[0].contact_j()[1], 2);
  const auto& normal = f[0].contacts->get<ValueTable<double>>("normal_force");
  EXPECT_EQ(normal(0, 0), -1.5);
  EXPECT_EQ(normal(1, 0), 2.5);
  EXPECT_EQ(f[0].contacts->get<Eigen::ArrayXd>("overlap")[1], 0.002);
  // The middle of the overlap on the line of the centres: 6 - (0.5 - 0.001).
  EXPECT_NEAR(f[0].contacts->get<ValueTable<double>>("point")(1, 0), 5.501, 1e-15);
  EXPECT_FALSE(f[0].contacts->has("tangential_force"));  // no force column: none
  EXPECT_EQ(f[1].contacts->rows(), 1);
  EXPECT_EQ(f[1].contact_i()[0], 1);
  EXPECT_EQ(f[1].contacts->get<ValueTable<double>>("normal_force")(0, 0), 1.5);
  EXPECT_TRUE(harness_->logged_lines().empty());  // contacts given: no precision warning
}

TEST_F(LammpsDumpContacts, WallEntriesGoToTheNearestStatedWall) {
  auto params = with_pairs(pair_snapshot(0, kPairs0, 2) + pair_snapshot(100, "", 0));
  // compute wall/gran/local pos id force_normal: the contact point, the atom's centre, the
  // mesh, the triangle and the atom, the normal force on the atom.
  const std::string walls =
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n"
      "0 10\nITEM: ENTRIES c_w[1] c_w[2] c_w[3] c_w[4] c_w[5] c_w[6] c_w[7] c_w[8] c_w[9] "
      "c_w[10] c_w[11] c_w[12]\n6 5 0 6 5 0.5 0 0 10 0 0 4\n";
  const std::string no_walls =
      "ITEM: TIMESTEP\n100\nITEM: NUMBER OF ENTRIES\n0\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n"
      "0 10\nITEM: ENTRIES c_w[1] c_w[2] c_w[3] c_w[4] c_w[5] c_w[6] c_w[7] c_w[8] c_w[9] "
      "c_w[10] c_w[11] c_w[12]\n";
  params["wall_file"] = write(walls + no_walls, "walls.dump");
  params["wall_columns"] = "pos id force_normal";
  const auto f = frames(params);
  ASSERT_EQ(f[0].contacts->rows(), 3);
  EXPECT_EQ(f[0].contact_i()[2], 3);
  EXPECT_EQ(f[0].contact_j()[2], partner::wall(Wall::ZLow));
  EXPECT_EQ(f[0].contacts->get<ValueTable<double>>("normal_force")(2, 2), 4.0);
  EXPECT_EQ(f[0].contacts->get<ValueTable<double>>("point")(2, 0), 6.0);
  EXPECT_EQ(f[0].contacts->get<Eigen::ArrayXd>("overlap")[2], 0.0);  // from the centre
  // An atom touching a mesh wall at two facets has two entries, with two points; one entry
  // written twice doubled the base contacts (exit 0).
  const std::string two =
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n2\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n"
      "0 10\nITEM: ENTRIES c_w[1] c_w[2] c_w[3] c_w[4] c_w[5] c_w[6] c_w[7] c_w[8] c_w[9] "
      "c_w[10] c_w[11] c_w[12]\n6 5 0 6 5 0.5 0 0 10 0 0 4\n";
  params["wall_file"] = write(two + "5.9 5 0 6 5 0.5 0 1 10 0 0 4\n" + no_walls, "facets.dump");
  EXPECT_EQ(frames(params)[0].contacts->rows(), 4);
  params["wall_file"] = write(two + "6 5 0 6 5 0.5 0 0 10 0 0 4\n" + no_walls, "twice.dump");
  EXPECT_EQ(refusal(params),
            "twice.dump: timestep 0, line 11: expected each wall contact once, got the same entry "
            "again (first on line 10)");
}

// The tangential force named as the normal one (90 degrees off the line of the centres) was
// read as it, exit 0. A dashpot's attractive pairs, their force reversed along the line, are
// read (a damped bed may have nine in ten of its few loaded pairs parting).
TEST_F(LammpsDumpContacts, NormalForcesOffTheLineOfTheCentresAreRefused) {
  const std::string empty_100 = pair_snapshot(100, "", 0);
  const auto with_precise_pairs = [&](const std::string& pairs) {
    nlohmann::json params = with_pairs(pairs);
    params["file"] = write(precise_atoms(), "precise.dump");
    return params;
  };
  EXPECT_EQ(refusal(with_precise_pairs(pair_snapshot(0, "1 2 0 0 -1.5 0 0\n", 1) + empty_100)),
            "pairs.dump: timestep 0, line 10: expected the normal force (columns 4 to 6) along "
            "the line of atoms 1 and 2's centres, got it 90 degrees off it (8.10971 allowed): are "
            "the columns named as the file has them?");
  EXPECT_EQ(refusal(with_precise_pairs(pair_snapshot(0, "1 2 0 1.5 0 0 0\n10 3 0 -2.5 0 0 0\n", 2) +
                                       empty_100)),
            "accepted");
}

// A wall file of another snapshot or run: an atom away from the wall the entry names, or an
// overlap (delta) its position contradicts, is refused, not stored as a contact.
TEST_F(LammpsDumpContacts, AWallContactMustBeWhereItsAtomIs) {
  auto one_wall = [&](const std::string& columns, const std::string& entry) {
    nlohmann::json params;
    std::string header =
        "ITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 10\nITEM: ENTRIES";
    std::istringstream words(entry);
    int count = 0;
    for (std::string w; words >> w;) header += " c_w[" + std::to_string(++count) + "]";
    header += "\n";
    params["file"] = write(precise_atoms(), "atoms.dump");
    params["wall_file"] = write(
        "ITEM: TIMESTEP\n0\n" + header + entry + "\nITEM: TIMESTEP\n100\n" + header + entry + "\n",
        "walls.dump");
    params["wall_columns"] = columns;
    return params;
  };
  auto overlap = [&](const nlohmann::json& params) {
    return frames(params)[0].contacts->get<Eigen::ArrayXd>("overlap")[0];
  };
  // Atom 1 at height 2, radius 0.5: 1.5 above the base.
  EXPECT_EQ(refusal(one_wall("pos id force_normal", "1.000000 5.000000 0 1 5 2 0 0 1 0 0 4")),
            "walls.dump: timestep 0, line 10: expected an atom that touches a wall, got a gap of "
            "1.5 (atom 1's centre 2 from the wall at the entry's point, radius 0.5, positions "
            "known to 2.73255e-06)");
  EXPECT_EQ(refusal(one_wall("id force_normal", "0 0 1 0 0 4")),
            "walls.dump: timestep 0, line 10: expected an atom that touches a wall, got a gap of "
            "1.5 (atom 1's centre 2 from the wall nearest it, radius 0.5, positions known to "
            "1.73255e-06)");
  // Atom 10 rests on the base: no overlap, whatever delta says.
  EXPECT_EQ(refusal(one_wall("id force_normal delta", "0 0 10 0 0 4 0.3")),
            "walls.dump: timestep 0, line 10: expected an overlap of 0 in column 7 (atom 10's "
            "centre 0.5 from the wall nearest it, radius 0.5, to within 0.0500017), got 0.3");
  EXPECT_EQ(overlap(one_wall("id force_normal delta", "0 0 10 0 0 4 0.0")), 0.0);
  // A point on the surface of a wall that moved (a vibrated base now at 0.1): its own gap.
  EXPECT_NEAR(
      overlap(one_wall("pos id force_normal", "6.000000 5.000000 0.1000000 6 5 0.5 0 0 10 0 0 4")),
      0.1, 1e-15);
  // A point beside atom 1 (a side wall the container does not state) went to the base, the
  // stated wall nearest to it, and counted as a base contact (exit 0).
  EXPECT_EQ(
      refusal(one_wall("pos id force_normal", "0.5000000 5.000000 2.000000 1 5 2 0 0 1 4 0 0")),
      "walls.dump: timestep 0, line 10: expected the point of atom 1's wall contact within "
      "25.8 degrees of a stated wall's normal, got it 90 degrees off the closest, z_low's: a "
      "wall the container does not state? (state its base, cylinder_radius or side_walls)");
}

// A shaken base is stated where it is lowest: a bead touching the base, raised by more than
// a radius, and a side wall had its point nearer the side wall than the stated base, went
// to the side wall and was refused as off its normal. The wall the point faces is the one.
TEST_F(LammpsDumpContacts, AWallContactGoesToTheWallItsPointFaces) {
  const std::string box = "ITEM: BOX BOUNDS ff ff ff\n0 10\n0 10\n0 10\n";
  const std::string atoms = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\n" + box +
                            "ITEM: ATOMS id type x y z radius\n1 1 1 5 2 0.5\n";
  // The point 0.5 below atom 1's centre: 1 from the side wall x = 0, 1.5 from the base z = 0.
  const std::string walls = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n1\n" + box +
                            "ITEM: ENTRIES c_w[1] c_w[2] c_w[3] c_w[4] c_w[5] c_w[6] c_w[7] c_w[8] "
                            "c_w[9] c_w[10] c_w[11] c_w[12]\n1 5 1.5 1 5 2 0 0 1 0 0 4\n";
  const auto f = frames({{"file", write(atoms, "atoms.dump")},
                         {"wall_file", write(walls, "walls.dump")},
                         {"wall_columns", "pos id force_normal"},
                         {"side_walls", {0, 10, 0, 10}}});
  ASSERT_EQ(f.at(0).contacts->rows(), 1);
  EXPECT_EQ(f[0].contact_j()[0], partner::wall(Wall::ZLow));
  EXPECT_EQ(f[0].contacts->get<Eigen::ArrayXd>("overlap")[0], 0.0);  // from the point
}

// In a cylinder of radius 5 about (5, 5): a contact whose point lies outward of atom 1 is
// the cylinder's; one whose point lay across the axis from the atom's centre took the
// cylinder's normal at the point, faced it, and was read as a cylinder contact (exit 0).
TEST_F(LammpsDumpContacts, ACylinderContactFacesTheCylinderFromTheAtomsCentre) {
  const std::string box = "ITEM: BOX BOUNDS ff ff ff\n0 10\n0 10\n0 10\n";
  const auto contact_of = [&](const std::string& centre, const std::string& point) {
    const std::string atoms = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\n" + box +
                              "ITEM: ATOMS id type x y z radius\n1 1 " + centre + " 0.5\n";
    const std::string walls =
        "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n1\n" + box +
        "ITEM: ENTRIES c_w[1] c_w[2] c_w[3] c_w[4] c_w[5] c_w[6] c_w[7] c_w[8] c_w[9] c_w[10] "
        "c_w[11] c_w[12]\n" +
        point + " " + centre + " 0 0 1 1 0 0\n";
    const nlohmann::json params = {
        {"file", write(atoms, "atoms.dump")},    {"wall_file", write(walls, "walls.dump")},
        {"wall_columns", "pos id force_normal"}, {"cylinder_radius", 5.0},
        {"cylinder_axis", {5.0, 5.0}},           {"top", 10.0}};
    return params;
  };
  const auto f = frames(contact_of("9.5 5 2", "10 5 2"));
  ASSERT_EQ(f.at(0).contacts->rows(), 1);
  EXPECT_EQ(f[0].contact_j()[0], partner::wall(Wall::CylinderSide));
  EXPECT_EQ(refusal(contact_of("5.2 5 2", "4.7 5 2")),
            "walls.dump: timestep 0, line 10: expected the point of atom 1's wall contact within "
            "25.8 degrees of a stated wall's normal, got it 90 degrees off the closest, z_low's: a "
            "wall the container does not state? (state its base, cylinder_radius or side_walls)");
}

TEST_F(LammpsDumpContacts, BadPairFilesAreRefusedWithTheirLine) {
  const std::string second = pair_snapshot(100, "", 0);
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, "1 7 0 -1.5 0 0 0.001\n", 1) + second)),
            "pairs.dump: timestep 0, line 10: expected the id of an atom of timestep 0 of "
            "atoms.dump in column 2, got 7, which it does not hold");
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, kPairs0, 2) + pair_snapshot(50, "", 0) + second)),
            "pairs.dump: timestep 50, line 12: expected a snapshot of atoms.dump's timesteps, "
            "got one atoms.dump does not have");
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, kPairs0, 2))),
            "pairs.dump: expected a snapshot of timestep 100 (timestep 100 of atoms.dump), got "
            "none");
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, "1 2 0 -1.5 0 0\n", 1) + second)),
            "pairs.dump: timestep 0, line 10: expected 7 values, as params.pair_columns's "
            "keywords give, got 6: \"1 2 0 -1.5 0 0\"");
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, "1 2 0 -1.5 nan 0 0.001\n", 1) + second)),
            "pairs.dump: timestep 0, line 10: expected a finite number in column 5, got \"nan\"");
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, "1 1 0 -1.5 0 0 0.001\n", 1) + second)),
            "pairs.dump: timestep 0, line 10: expected two different atoms, got id 1 twice");
  auto wrong_columns = with_pairs(pair_snapshot(0, kPairs0, 2) + second);
  wrong_columns["pair_columns"] = "id force_normal";
  EXPECT_EQ(refusal(wrong_columns),
            "pairs.dump: timestep 0, line 9: expected 6 columns, as params.pair_columns's "
            "keywords give, got 7");
  wrong_columns["pair_columns"] = "id delta";
  EXPECT_EQ(refusal(wrong_columns),
            "params.pair_columns: expected the keywords id and force_normal, got \"id delta\"");
  wrong_columns["pair_columns"] = "id force_normal overlap";
  EXPECT_EQ(refusal(wrong_columns),
            "params.pair_columns: expected keywords of compute pair/gran/local or "
            "wall/gran/local (pos vel id force force_normal force_tangential torque "
            "contactArea delta heatFlux), got \"overlap\"");
  auto lammps = with_pairs(pair_snapshot(0, kPairs0, 2) + second);
  lammps["pair_format"] = "lammps";
  lammps["pair_columns"] = "patom1 patom2 fx fy eng p4 p5";
  EXPECT_EQ(refusal(lammps),
            "params.pair_columns: expected patom1 patom2 fx fy fz, got \"patom1 patom2 fx fy eng "
            "p4 p5\"");
  lammps["pair_columns"] = "patom1 patom2 fx fy fz p1 p2";
  EXPECT_EQ(refusal(lammps),
            "params.pair_columns: expected p1 p2 p3 (the tangential force) together, got "
            "\"patom1 patom2 fx fy fz p1 p2\"");
  lammps["pair_columns"] = "patom1 patom2 fx fy fz eng p4";
  lammps["wall_file"] = lammps["pair_file"];
  lammps["wall_columns"] = "patom1 patom2 fx fy fz eng p4";
  EXPECT_EQ(refusal(lammps),
            "params.wall_file: expected no wall file with pair_format \"lammps\" (LAMMPS has no "
            "compute of wall contacts), got pairs.dump");
  EXPECT_EQ(refusal({{"file", write(atom_snapshot(0), "one.dump")},
                     {"pair_file", write(atom_snapshot(0), "atoms_again.dump")},
                     {"pair_columns", "id force_normal delta"}}),
            "atoms_again.dump: timestep 0, line 3: expected \"ITEM: NUMBER OF ENTRIES\", got "
            "\"ITEM: NUMBER OF ATOMS\": a dump of atoms, not a dump local");
}

// Without the contact files, their format and columns did nothing, without a word.
TEST_F(LammpsDumpContacts, ContactSettingsWithoutTheirFileAreRefused) {
  const std::string atoms = write(atom_snapshot(0), "atoms.dump");
  EXPECT_EQ(refusal({{"file", atoms}, {"pair_columns", "id force_normal"}}),
            "test: params.pair_columns: expected its default \"\" (it acts only with a "
            "pair_file), got \"id force_normal\"");
  EXPECT_EQ(refusal({{"file", atoms}, {"wall_columns", "id force_normal"}}),
            "test: params.wall_columns: expected its default \"\" (it acts only with a "
            "wall_file), got \"id force_normal\"");
  EXPECT_EQ(refusal({{"file", atoms}, {"pair_format", "lammps"}}),
            "test: params.pair_format: expected its default \"liggghts\" (it acts only with a "
            "pair_file or wall_file), got \"lammps\"");
}

// A pair listed twice, in either order (LAMMPS lists a pair across two processors twice
// with newton_pair off), was read as two contacts: coordination, networks and the force
// PDF counted it twice, exit 0.
TEST_F(LammpsDumpContacts, APairListedTwiceIsRefused) {
  const std::string second = pair_snapshot(100, "", 0);
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, kPairs0 + "2 1 0 1.5 0 0 0.001\n", 3) + second)),
            "pairs.dump: timestep 0, line 12: expected each pair of atoms once, got ids 1 and 2 "
            "again (first on line 10)");
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, kPairs0 + "10 3 0 2.5 0 0 0.002\n", 3) + second)),
            "pairs.dump: timestep 0, line 12: expected each pair of atoms once, got ids 3 and 10 "
            "again (first on line 11)");
}

// A pair that does not touch was read as a contact (z 4.53 for 4.5 from a pair 8 radii
// apart, exit 0): LAMMPS lists every pair within its cutoff without `cutoff radius`, and a
// dump of another run lists pairs anywhere.
TEST_F(LammpsDumpContacts, APairThatDoesNotTouchIsRefused) {
  EXPECT_EQ(refusal(with_pairs(pair_snapshot(0, "1 3 0 -1.5 0 0 0.001\n", 1) +
                               pair_snapshot(100, "", 0))),
            "pairs.dump: timestep 0, line 10: expected atoms 1 and 3 that touch, got a gap of "
            "3.272 between them (centres 4.272 apart, radii summing to 1, positions known to "
            "1.73205): give only contacts (LAMMPS: compute pair/local ... cutoff radius)");
  // Printed to 17 digits, a gap of 1e-6 radii is seen; touching to rounding is a contact.
  auto two_atoms = [&](const std::string& x2) {
    const std::string atoms =
        "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 "
        "10\nITEM: ATOMS id type x y z radius\n1 1 1.0000000000000000 5 2 0.5\n2 1 " +
        x2 + " 5 2 0.5\n";
    return nlohmann::json{
        {"file", write(atoms, "atoms.dump")},
        {"pair_file", write(pair_snapshot(0, "1 2 0 -1.5 0 0 0\n", 1), "pairs.dump")},
        {"pair_columns", "id force_normal delta"}};
  };
  EXPECT_EQ(
      refusal(two_atoms("2.0000005000000000")).substr(0, 87),
      "pairs.dump: timestep 0, line 10: expected atoms 1 and 2 that touch, got a gap of 5e-07 ");
  EXPECT_EQ(frames(two_atoms("2.0000000000000004"))[0].contacts->rows(), 1);
}

// A pair's own distance or overlap column was never held against the positions: LAMMPS'
// dist -5 for atoms 1 apart stored an overlap of 6, exit 0. It agrees to the rounding of
// the positions and of the word written, or the line is refused.
TEST_F(LammpsDumpContacts, APairsDistanceOrOverlapMustBeWhereItsAtomsAre) {
  const std::string atoms =
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 "
      "10\nITEM: ATOMS id type x y z radius\n1 1 1.000000 5 2 0.5\n2 1 1.999000 5 2 0.5\n";
  auto one_pair = [&](const std::string& columns, const std::string& entry) {
    const bool lammps = columns.find("patom1") != std::string::npos;
    return nlohmann::json{
        {"pair_format", lammps ? "lammps" : "liggghts"},
        {"file", write(atoms, "atoms.dump")},
        {"pair_file",
         write("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS pp pp ff\n0 "
               "10\n0 10\n0 10\nITEM: ENTRIES c_1[1] c_1[2] c_1[3] c_1[4] c_1[5] c_1[6] "
               "c_1[7]\n" +
                   entry + "\n",
               "pairs.dump")},
        {"pair_columns", columns}};
  };
  auto overlap = [&](const nlohmann::json& params) {
    return frames(params)[0].contacts->get<Eigen::ArrayXd>("overlap")[0];
  };
  const std::string lammps = "patom1 patom2 dist fx fy fz eng";
  const std::string liggghts = "id force_normal delta";
  EXPECT_EQ(refusal(one_pair(lammps, "1 2 -5 -1.5 0 0 0")),
            "pairs.dump: timestep 0, line 10: expected a distance of 0.999 in column 3 (atoms 1 "
            "and 2 as the snapshot places them, to within 0.500002), got -5");
  EXPECT_EQ(refusal(one_pair(liggghts, "1 2 0 -1.5 0 0 0.7")),
            "pairs.dump: timestep 0, line 10: expected an overlap of 0.001 in column 7 (atoms 1 "
            "and 2 as the snapshot places them, to within 0.0500017), got 0.7");
  EXPECT_NEAR(overlap(one_pair(lammps, "1 2 0.999 -1.5 0 0 0")), 0.001, 1e-12);
  // dist printed with %g as "1" says 0.5 to 1.5; the positions' 0.999 is the one kept.
  EXPECT_NEAR(overlap(one_pair(lammps, "1 2 1 -1.5 0 0 0")), 0.001, 1e-12);
  // %g prints atom 1234567 as 1.23457e+06, which named atom 1234570 when there was one.
  EXPECT_EQ(refusal(one_pair(lammps, "1.23457e+06 2 0.999 -1.5 0 0 0")),
            "pairs.dump: timestep 0, line 10: expected an atom id written to its last digit in "
            "column 1, got \"1.23457e+06\" (write the ids with %d: dump_modify format)");
  EXPECT_NEAR(overlap(one_pair(liggghts, "1 2 0 -1.5 0 0 0.001")), 0.001, 1e-12);
}

TEST_F(LammpsDumpContacts, PositionsPrintedWithPercentGAreWarnedAbout) {
  const std::string header =
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 "
      "10\nITEM: ATOMS id type x y z radius\n";
  // %.17g: a centre distance known to 4e-16, well within the tolerance.
  frames({{"file", write(header + "1 1 1.2345678901234567 5 2 0.5\n2 1 2.2345678901234567 5 2 "
                                  "0.5\n",
                         "g17.dump")},
          {"dt", 0.001}});
  EXPECT_TRUE(harness_->logged_lines().empty());
  // %g: each coordinate within 5e-6 of the printed one, a centre within 8.7e-6.
  frames({{"file", write(header + "1 1 1.23457 5 2 0.5\n2 1 2.23457 5 2 0.5\n", "g.dump")},
          {"dt", 0.001}});
  const auto log = harness_->logged_lines();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("g.dump: positions printed to 6 significant digits: a centre distance "
                        "is known to 1.73205e-05, 1.73205e-05 of the smallest contact distance "
                        "(1), coarser "
                        "than the contact_tolerance 1e-09 by which analyzers find contacts from "
                        "positions: give the run's contacts (pair_file) or write positions with "
                        "dump_modify format float %.17g"),
            std::string::npos)
      << log[0];
}

// The committed LAMMPS sample (tests/lammps_runs/in.lammps_bed): every entry of its pair
// dump a contact row, with the atoms its patom1 and patom2 name and fx fy fz as the normal
// force, the total |F_n| as a direct parse of the text gives it.
TEST_F(LammpsDumpContacts, TheLammpsSamplesContactsAreItsPairEntries) {
  const fs::path data = GRANPIPE_DATA_SAMPLES;
  gzFile in = gzopen((data / "lammps_bed_pairs.dump.gz").c_str(), "rb");
  ASSERT_NE(in, nullptr);
  std::map<std::int64_t, std::pair<long, double>> want;  // timestep: entries, sum |F_n|
  std::string text;
  for (char buffer[1 << 16]; int n = gzread(in, buffer, sizeof buffer);) text.append(buffer, n);
  gzclose(in);
  std::istringstream lines(text);
  for (std::string item, line; std::getline(lines, item);) {
    std::int64_t step = 0;
    long count = 0;
    lines >> step >> std::ws;
    std::getline(lines, line);  // NUMBER OF ENTRIES
    lines >> count >> std::ws;
    for (int k = 0; k < 5; ++k) std::getline(lines, line);  // box, ENTRIES
    double total = 0;
    for (long e = 0; e < count; ++e) {
      double id1, id2, dist, fx, fy, fz, p1, p2, p3;
      lines >> id1 >> id2 >> dist >> fx >> fy >> fz >> p1 >> p2 >> p3 >> std::ws;
      total += std::sqrt(fx * fx + fy * fy + fz * fz);
    }
    want[step] = {count, total};
  }
  const auto f = frames({{"file", (data / "lammps_bed.dump.gz").string()},
                         {"pair_file", (data / "lammps_bed_pairs.dump.gz").string()},
                         {"pair_format", "lammps"},
                         {"pair_columns", "patom1 patom2 dist fx fy fz p1 p2 p3"},
                         {"base", -0.0008}});
  ASSERT_EQ(f.size(), want.size());
  for (const Frame& frame : f) {
    const auto& [count, total] = want.at(frame.step);
    ASSERT_EQ(frame.contacts->rows(), count) << frame.step;
    const auto& normal = frame.contacts->get<ValueTable<double>>("normal_force");
    EXPECT_NEAR(normal.matrix().rowwise().norm().sum(), total, 1e-12 * total) << frame.step;
    EXPECT_TRUE(frame.contacts->has("tangential_force"));
  }
}

// A pair across the periodic x sides: the overlap from the nearest image (no delta column)
// and the contact point wrapped into the box.
TEST_F(LammpsDumpContacts, APairAcrossAPeriodicSideMeetsThroughTheNearestImage) {
  const std::string atoms =
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 "
      "10\nITEM: ATOMS id type x y z radius\n1 1 0.25 5 2 0.5\n2 1 9.375 5 2 0.5\n";
  const std::string pairs =
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS pp pp ff\n0 10\n0 10\n0 "
      "10\nITEM: ENTRIES c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6]\n1 2 1 3 0 0\n";
  const auto f = frames({{"file", write(atoms, "atoms.dump")},
                         {"pair_file", write(pairs, "pairs.dump")},
                         {"pair_columns", "id force_normal"}});
  ASSERT_EQ(f.at(0).contacts->rows(), 1);
  EXPECT_EQ(f[0].contacts->get<Eigen::ArrayXd>("overlap")[0], 0.125);  // 1 - 0.875
  // 0.25 - (0.5 - 0.0625) = -0.1875, wrapped to 9.8125.
  EXPECT_EQ(f[0].contacts->get<ValueTable<double>>("point")(0, 0), 9.8125);
}
