// The packing analyzer on crystals from the `lattice` plugin (loaded like any plugin):
// closed-form packing fractions and coordination numbers, translation invariance of
// regions cut anywhere, the stereological profile against the exact volume, and the
// shared contact list.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>

#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/cut_profile.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/overlap.hpp"
#include "granpipe/region.hpp"
#include "packing_analyzer.hpp"
#include "plugin_harness.hpp"

namespace {

using granpipe::Frame;
using granpipe::FrameCache;
using granpipe::Region;
using granpipe::packing::measure_packing;
using granpipe::packing::PackingMeasurement;
using granpipe::packing::PackingSettings;

constexpr double kPi = std::numbers::pi;

struct Expected {
  std::string name;
  double phi;
  int z;
};

const std::vector<Expected>& lattices() {
  static const std::vector<Expected> all{
      {"square", kPi / 4, 4},
      {"triangular", kPi / (2 * std::sqrt(3.0)), 6},
      {"sc", kPi / 6, 6},
      {"bcc", kPi * std::sqrt(3.0) / 8, 8},
      {"fcc", kPi / (3 * std::sqrt(2.0)), 12},
      {"hcp", kPi / (3 * std::sqrt(2.0)), 12},
  };
  return all;
}

// Frames of the installed `lattice` source plugin with these parameters.
std::vector<Frame> lattice(const nlohmann::json& set, std::uint64_t seed = 3) {
  const auto ctx = granpipe::test::make_context("lattice", set, seed);
  auto source = granpipe::test::installed_plugins().find("lattice")->make_source(*ctx);
  std::vector<Frame> frames;
  Frame f;
  while (source->next(f)) {
    f.check("packing test");
    frames.push_back(f);
  }
  return frames;
}

Frame one(const std::string& name, const std::string& boundary = "periodic",
          nlohmann::json more = nlohmann::json::object()) {
  more["lattice"] = name;
  more["boundary"] = boundary;
  return lattice(more).at(0);
}

PackingMeasurement measure(const Frame& f, PackingSettings s = {}) {
  FrameCache cache;
  return measure_packing(f, cache, s);
}

TEST(Packing, PeriodicLatticesHaveTheirPackingFraction) {
  for (const auto& e : lattices()) {
    const Frame f = one(e.name, "periodic", {{"radius", 0.3}});
    const PackingMeasurement m = measure(f);
    EXPECT_NEAR(m.phi, e.phi, 1e-12 * e.phi) << e.name;
    double volume = 1;
    for (int a = 0; a < f.dim; ++a) volume *= f.container.length(a);
    EXPECT_EQ(m.centres, f.size()) << e.name;
    EXPECT_DOUBLE_EQ(m.number_density, f.size() / volume) << e.name;
    // Stereology: the mean cut fraction is the same packing fraction, up to the bias of
    // cuts at fixed heights through layers aligned with them (largest in 2D: chords).
    EXPECT_NEAR(m.phi_cuts, e.phi, 5e-4) << e.name;
  }
}

TEST(Packing, CoordinationOfExactlyTouchingLattices) {
  for (const auto& e : lattices()) {
    Frame f = one(e.name);
    const PackingMeasurement touching = measure(f);
    EXPECT_DOUBLE_EQ(touching.z_mean, e.z) << e.name;
    EXPECT_DOUBLE_EQ(touching.z_mean_with_walls, e.z) << e.name;  // no walls
    f.radius() *= 1 - 1e-6;  // a gap a thousand times the tolerance
    const PackingMeasurement apart = measure(f);
    EXPECT_EQ(apart.z_mean, 0.0) << e.name;
  }
}

// One cell of a simple cubic crystal holds one sphere touching its six images: z came out
// 0 (the pair loop had no pair), where two spheres in so small a box are refused.
TEST(Packing, ALoneSphereTouchingItsImagesIsRefusedAsPairsAre) {
  const Frame f = one("sc", "periodic", {{"cells", {1, 1, 1}}});
  ASSERT_EQ(f.size(), 1);
  const std::string refused = granpipe::test::input_error_of([&] { measure(f); });
  EXPECT_NE(refused.find("expected a periodic box of length at least"), std::string::npos)
      << refused;
}

// Contact counts are relative to particle size: the same crystal at any scale.
TEST(Packing, ContactsDoNotDependOnTheScale) {
  for (double radius : {1e-4, 1.0, 1e4}) {
    const Frame f = one("fcc", "periodic", {{"radius", radius}});
    EXPECT_DOUBLE_EQ(measure(f).z_mean, 12) << radius;
  }
}

// Simple cubic crystal of 4 x 4 x 4 in a tight box open at the top: 5 walls with 16
// particles each, 3 x 3 x 16 pairs along each axis.
TEST(Packing, WallContactsInATightBox) {
  const Frame f = one("sc", "walls");
  const PackingMeasurement m = measure(f);
  EXPECT_DOUBLE_EQ(m.z_mean, 2.0 * 144 / 64);
  EXPECT_DOUBLE_EQ(m.z_mean_with_walls, (2.0 * 144 + 80) / 64);
  EXPECT_NEAR(m.phi, kPi / 6, 1e-12);  // the top is the top of the particles
  const auto c = granpipe::find_contacts_by_distance(f, 1e-9);
  EXPECT_EQ(c.pairs, 144);
  EXPECT_EQ(c.wall_contacts(), 80);
  for (Eigen::Index k = 0; k < c.size(); ++k) EXPECT_NEAR(c.gap[k], 0.0, 1e-12);
}

// A region of a whole number of unit cells placed anywhere in a periodic crystal (here
// across the periodic boundary too) holds exactly the crystal's packing fraction, since
// the lattice's period integral does not depend on where the period starts. Every
// particle the region cuts, and every periodic image, must be counted right.
TEST(Packing, RegionOfWholeCellsAtAnyOffsetHasTheLatticeFraction) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.5, 1.0);
  const std::map<std::string, std::vector<int>> per_axis{{"square", {4, 4}}, {"triangular", {4, 4}},
                                                         {"sc", {4, 4, 4}},  {"bcc", {4, 4, 4}},
                                                         {"fcc", {4, 4, 4}}, {"hcp", {4, 4, 4}}};
  for (const auto& e : lattices()) {
    const Frame f = one(e.name, "periodic", {{"radius", 0.8}});
    const int dim = f.dim;
    for (int trial = 0; trial < 5; ++trial) {
      Region region;
      region.dim = dim;
      for (int a = 0; a < dim; ++a) {
        const double cell = f.container.length(a) / per_axis.at(e.name)[a];
        region.lo[a] = u(rng) * f.container.length(a);
        region.hi[a] = region.lo[a] + (1 + trial % 3) * cell;
      }
      const double phi = granpipe::particle_measure_in(f, region) / region.volume();
      EXPECT_NEAR(phi, e.phi, 1e-12 * e.phi) << e.name << " trial " << trial;
    }
  }
}

// Two independent computations of the same slab: the exact volume of the particles in
// it, and the mean area fraction of horizontal cuts through it (2D: chord lengths).
TEST(Packing, CutProfileIntegratesToTheSlabVolumeFraction) {
  for (const std::string name : {"triangular", "square", "fcc", "bcc"}) {
    const Frame f = one(name, "walls", {{"jitter", 0.3}});
    PackingSettings s;
    s.exclude_bottom = 0.83;
    s.exclude_top = 0.61;
    s.exclude_sides = 0.37;
    s.cuts_step = 0.001;
    const PackingMeasurement m = measure(f, s);
    EXPECT_GT(m.phi, 0.2) << name;  // radii shrunk by the jitter to 0.7
    EXPECT_NEAR(m.phi_cuts, m.phi, 5e-6 * m.phi) << name;
    // Coarser cuts: still the same estimate, less precisely.
    s.cuts_step = 0.05;
    EXPECT_NEAR(measure(f, s).phi_cuts, m.phi, 3e-3 * m.phi) << name;
  }
}

// The cut fraction of a square crystal of touching disks at height h from a row of
// centres is the chord over the spacing: sqrt(1 - (h/r)^2); of a simple cubic crystal,
// the disc area over the cell face: pi (r^2 - h^2) / (2r)^2.
TEST(Packing, ProfileOfCrystalsMatchesChordsAndDiscs) {
  for (const std::string name : {"square", "sc"}) {
    const Frame f = one(name, "walls");
    PackingSettings s;
    s.profile_step = 0.1;
    const PackingMeasurement m = measure(f, s);
    const double r = 0.5, d = 1.0;
    ASSERT_EQ(m.profile.size(), 40u) << name;  // 4 layers of one diameter
    for (std::size_t k = 0; k < m.profile.size(); ++k) {
      const double y = (k + 0.5) * s.profile_step * d;
      const double h = std::fmod(y, d) - r;  // from the centre of the layer
      const double expected =
          name == "square" ? std::sqrt(1 - h * h / (r * r)) : kPi * (r * r - h * h) / (d * d);
      EXPECT_NEAR(m.profile[k], expected, 1e-12) << name << " cut " << k;
    }
  }
}

TEST(Packing, ContactListIsSharedThroughTheFrameCache) {
  const Frame f = one("bcc");
  FrameCache cache;
  PackingSettings s;
  s.tolerance = 1e-7;
  measure_packing(f, cache, s);
  const auto& shared =
      cache.get<granpipe::DistanceContacts>(granpipe::contacts_by_distance_key(1e-7), [] {
        ADD_FAILURE() << "the contacts were not in the cache";
        return granpipe::DistanceContacts{};
      });
  EXPECT_EQ(shared.pairs, 8 * f.size() / 2);
  EXPECT_EQ(shared.tolerance, 1e-7);
  EXPECT_NE(granpipe::contacts_by_distance_key(1e-7), granpipe::contacts_by_distance_key(1e-9));
}

TEST(Packing, ExcludedLayersAndFreeSurface) {
  // Square crystal, 4 x 4, walls: excluding one diameter at the bottom and at the top of
  // the surface leaves the two middle rows, whose fraction is pi/4 again.
  const Frame f = one("square", "walls");
  PackingSettings s;
  s.exclude_bottom = 1;
  s.exclude_top = 1;
  const PackingMeasurement m = measure(f, s);
  EXPECT_NEAR(m.phi, kPi / 4, 1e-13);
  EXPECT_EQ(m.centres, 8);
  EXPECT_NEAR(m.region.hi[1] - m.region.lo[1], 2.0, 1e-13);
  // An explicit surface top agrees with auto for an open-top box; a container top
  // includes the empty space above the particles (none here: the box is tight).
  s.top = granpipe::packing::Top::Surface;
  EXPECT_NEAR(measure(f, s).phi, m.phi, 1e-15);

  s.exclude_top = 3.5;  // nothing left
  EXPECT_THROW(measure(f, s), granpipe::InputError);
  PackingSettings surface;
  surface.top = granpipe::packing::Top::Surface;
  EXPECT_THROW(measure(one("square"), surface), granpipe::InputError);  // periodic top
}

// A lattice whose centres lie on the region's faces (excluding half a diameter): counted on
// the lower faces only, whatever the rounding. Before, number_density x (2R)^3 was 1, 1.728
// or 0.512 and z_mean 5.4, 5 or 6 as the radius changed.
TEST(Packing, CentresOnTheRegionsFacesAreCountedOnOneSide) {
  for (const double radius : {0.5, 0.05, 0.15, 0.3, 1.1}) {
    const Frame f = one("sc", "walls", {{"cells", {6, 6, 6}}, {"radius", radius}});
    PackingSettings s;
    s.exclude_bottom = s.exclude_top = s.exclude_sides = 0.5;
    s.top = granpipe::packing::Top::Surface;
    const PackingMeasurement m = measure(f, s);
    EXPECT_EQ(m.centres, 125) << "radius " << radius;  // 5 of 6 along each axis
    EXPECT_NEAR(m.number_density * std::pow(2.0 * radius, 3), 1.0, 1e-12) << "radius " << radius;
    EXPECT_NEAR(m.z_mean, 5.4, 1e-12) << "radius " << radius;  // a fifth miss one per axis
  }
  // Periodic: centres a hair below the box's bottom are wrapped to just below its top, and
  // every one is counted.
  Frame periodic = one("sc", "periodic", {{"cells", {6, 6, 6}}, {"radius", 0.5}});
  for (int a = 0; a < 3; ++a) {
    const double low = periodic.position().col(a).minCoeff();
    periodic.position().col(a) -= low - periodic.container.lo[a] + 1e-15;
  }
  EXPECT_EQ(measure(periodic).centres, periodic.size());
}

// Stacks of unit disks (or balls) standing in unit columns from the base up, the k-th
// stack `heights[k]` high: a heaped bed with known surface. 2D: one row of stacks;
// 3D: heights.size() = side * side stacks.
Frame stacks(const std::vector<int>& heights, int dim, int side = 0) {
  std::vector<std::array<double, 3>> centres;
  for (std::size_t k = 0; k < heights.size(); ++k) {
    const double x = dim == 2 ? k + 0.5 : static_cast<double>(k % side) + 0.5;
    const double z = dim == 2 ? 0.0 : static_cast<double>(k / side) + 0.5;
    for (int j = 0; j < heights[k]; ++j) centres.push_back({x, z, j + 0.5});
  }
  Frame f;
  f.resize(static_cast<Eigen::Index>(centres.size()), dim);
  f.radius().setConstant(0.5);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    f.position()(k, 0) = centres[i][0];
    if (dim == 3) f.position()(k, 1) = centres[i][1];
    f.position()(k, dim - 1) = centres[i][2];
  }
  const double w = dim == 2 ? static_cast<double>(heights.size()) : side;
  f.container = granpipe::Container::open_top_box(dim, {0, 0, 0}, {w, dim == 2 ? 20.0 : w, 20});
  return f;
}

TEST(Packing, LowestSurfaceKeepsTheRegionInsideAHeapedBed) {
  // Square stacks 5 4 6 3 5 4 high: the region under the lowest point of the surface
  // holds whole rows (pi/4); under the highest top it holds air beside the low stacks.
  const Frame f = stacks({5, 4, 6, 3, 5, 4}, 2);
  PackingSettings s;
  s.top = granpipe::packing::Top::LowestSurface;
  PackingMeasurement m = measure(f, s);
  EXPECT_DOUBLE_EQ(m.region.hi[1], 3.0);
  EXPECT_NEAR(m.phi, kPi / 4, 1e-13);
  EXPECT_EQ(m.centres, 18);
  s.exclude_top = 1;
  m = measure(f, s);
  EXPECT_DOUBLE_EQ(m.region.hi[1], 2.0);
  EXPECT_NEAR(m.phi, kPi / 4, 1e-13);
  // The profile still climbs the whole bed (6 rows), as with the highest top.
  EXPECT_EQ(m.profile.size(), 120u);

  s.top = granpipe::packing::Top::Surface;
  s.exclude_top = 0;
  EXPECT_NEAR(measure(f, s).phi, 27 * kPi / 4 / 36, 1e-13);

  // 3D: simple cubic stacks 3 high on a 3 x 3 floor, one of them 2 high. Balls of
  // neighbouring stacks only touch each other's columns, which does not count.
  const Frame g = stacks({3, 3, 3, 3, 2, 3, 3, 3, 3}, 3, 3);
  s.top = granpipe::packing::Top::LowestSurface;
  m = measure(g, s);
  EXPECT_DOUBLE_EQ(m.region.hi[2], 2.0);
  EXPECT_NEAR(m.phi, kPi / 6, 1e-13);
}

TEST(Packing, LowestSurfaceIn3DCountsTheDiscNotItsSquare) {
  // A 4 x 2 floor of unit columns, stacks 2 high, the one over [1, 2] x [1, 2] only 1 high.
  // A ball on top at (0.6, 0.6) spans that column in x and in y, but its disc stays
  // 0.57 from the column's corner: the column's surface stays at 1.
  std::vector<std::array<double, 3>> centres;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < (i == 1 && j == 1 ? 1 : 2); ++k)
        centres.push_back({i + 0.5, j + 0.5, k + 0.5});
  centres.push_back({0.6, 0.6, 2.5});
  Frame f;
  f.resize(static_cast<Eigen::Index>(centres.size()), 3);
  f.radius().setConstant(0.5);
  for (std::size_t n = 0; n < centres.size(); ++n)
    for (int a = 0; a < 3; ++a) f.position()(static_cast<Eigen::Index>(n), a) = centres[n][a];
  f.container = granpipe::Container::open_top_box(3, {0, 0, 0}, {4, 2, 20});
  f.check("floor");
  PackingSettings s;
  s.top = granpipe::packing::Top::LowestSurface;
  const PackingMeasurement m = measure(f, s);
  EXPECT_DOUBLE_EQ(m.region.hi[2], 1.0);
  EXPECT_NEAR(m.phi, kPi / 6, 1e-13);
}

TEST(Packing, LowestSurfaceSeesAcrossPeriodicSidesAndDownEmptyColumns) {
  // Four unit disks on the base of a box periodic in x, 4 wide, and two on top of them at
  // x = 0 (across the periodic side) and x = 2: every column of the four is covered up to
  // 2, the last one only by the image of the disk at x = 0.
  Frame f;
  f.resize(6, 2);
  f.position() << 0.5, 0.5, 1.5, 0.5, 2.5, 0.5, 3.5, 0.5, 0.0, 1.5, 2.0, 1.5;
  f.radius().setConstant(0.5);
  f.container = granpipe::Container::open_top_box(2, {0, 0, 0}, {4, 20, 1});
  f.container.boundary[0] = {granpipe::Boundary::Periodic, granpipe::Boundary::Periodic};
  PackingSettings s;
  s.top = granpipe::packing::Top::LowestSurface;
  EXPECT_DOUBLE_EQ(measure(f, s).region.hi[1], 2.0);

  // A stack missing down to the base leaves no bulk below the surface.
  try {
    measure(stacks({2, 2, 0, 2}, 2), s);
    ADD_FAILURE() << "a bed with an empty column has a bulk";
  } catch (const granpipe::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("y from 0 to 0"), std::string::npos) << e.what();
  }
}

TEST(Packing, CylinderContainersAreRefused) {
  Frame f = one("sc", "walls");
  f.container.shape = granpipe::ContainerShape::Cylinder;
  f.container.cylinder_radius = 10;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure(f); }),
            "packing: frame at step 0: expected a box container (the measuring region is a "
            "box), got a cylinder");
}

// The analyzer: per-frame values averaged with their standard errors, the profile table
// and its plot; frames without particles are skipped.
TEST(Packing, AnalyzerAveragesFrames) {
  const auto frames = lattice({{"lattice", std::string("triangular")},
                               {"boundary", std::string("walls")},
                               {"jitter", 0.2},
                               {"frames", std::int64_t{4}}});
  const auto ctx = granpipe::test::make_context(granpipe::packing::schema(),
                                                {{"exclude_bottom", 0.5}, {"profile_step", 0.25}});
  granpipe::packing::PackingAnalyzer analyzer(*ctx);
  granpipe::RunningMean phi, z;
  PackingSettings s;
  s.exclude_bottom = 0.5;
  s.profile_step = 0.25;
  for (const Frame& f : frames) {
    FrameCache cache;
    analyzer.consume(f, cache);
    const auto m = measure(f, s);
    phi.add(m.phi);
    z.add(m.z_mean);
  }
  Frame empty;
  empty.resize(0, 2);
  FrameCache cache;
  analyzer.consume(empty, cache);

  granpipe::Results r;
  analyzer.finish(r);
  EXPECT_EQ(r.scalar("frames").value, 4);
  EXPECT_DOUBLE_EQ(r.scalar("phi").value, phi.mean());
  EXPECT_DOUBLE_EQ(r.scalar("phi").uncertainty, phi.standard_error());
  EXPECT_GT(phi.standard_error(), 0.0);
  EXPECT_DOUBLE_EQ(r.scalar("z_mean").value, z.mean());
  EXPECT_NEAR(r.scalar("phi_cuts").value, phi.mean(), 0.01);
  EXPECT_GT(r.scalar("phi").value, 0.4);  // below the crystal's 0.9069 (0.8)^2 = 0.58: walls
  EXPECT_LT(r.scalar("phi").value, kPi / (2 * std::sqrt(3.0)) * 0.8 * 0.8);
  const auto& table = r.tables().at("profile");
  ASSERT_EQ(table.columns, (std::vector<std::string>{"height", "phi", "phi_err"}));
  ASSERT_GT(table.rows(), 10u);
  EXPECT_DOUBLE_EQ(table.column("height")[0], 0.125);
  EXPECT_EQ(r.plots().at("profile").table, "profile");
  EXPECT_TRUE(r.scalars().count("number_density"));
  EXPECT_TRUE(r.scalars().count("z_mean_with_walls"));
}

// Through a periodic side shorter than two contact distances a pair would touch twice.
TEST(Packing, TooShortPeriodicBoxIsRefusedForContacts) {
  const Frame f =
      lattice({{"lattice", std::string("sc")}, {"cells", std::vector<std::int64_t>{2, 3, 3}}})
          .at(0);
  EXPECT_THROW(granpipe::find_contacts_by_distance(f, 1e-9), granpipe::InputError);
}

TEST(Packing, OneParticle) {
  Frame f;
  f.resize(1, 3);
  f.position().row(0) << 1.0, 1.0, 1.0;
  f.radius()[0] = 1.0;
  f.container = granpipe::Container::open_top_box(3, {0, 0, 0}, {2, 2, 2});
  const auto m = measure(f);
  EXPECT_NEAR(m.phi, kPi / 6, 1e-14);  // sphere in its bounding cube
  EXPECT_EQ(m.z_mean, 0.0);
  EXPECT_EQ(m.z_mean_with_walls, 5.0);  // four sides and the base
}

}  // namespace

// The analyzer publishes each particle's coordination: 12 for every sphere of a periodic
// fcc crystal, 6 for every disk of a triangular one.
TEST(Packing, PublishesTheCoordinationOfEachParticle) {
  for (const auto& [name, z] : {std::pair{"fcc", 12}, {"triangular", 6}}) {
    const Frame f = one(name);
    const auto ctx =
        granpipe::test::make_context(granpipe::packing::schema(), {{"contact_tolerance", 1e-9}});
    granpipe::packing::PackingAnalyzer analyzer(*ctx);
    FrameCache cache;
    analyzer.consume(f, cache);
    granpipe::PropertyTable columns(granpipe::Scope::Particle, f.size(), f.dim);
    columns.add(granpipe::packing::PackingAnalyzer::coordination_property());
    analyzer.publish(columns);
    const granpipe::IntArray& c = columns.get<granpipe::IntArray>("coordination");
    ASSERT_EQ(c.size(), f.size()) << name;
    EXPECT_TRUE((c == z).all()) << name << ": " << c.minCoeff() << " to " << c.maxCoeff();
  }
}

// A step far too small for the bed (a typo, or another unit) asked for more cuts than an
// int counts: the count wrapped around to an empty profile, or one cut for phi_cuts
// (0.71 where phi is 0.64), exit 0. It is refused before anything is cut.
TEST(Packing, StepsThatDoNotFitTheBedAreRefused) {
  const Frame f = one("sc", "walls");
  PackingSettings profile;
  profile.profile_step = 1e-12;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure(f, profile); }),
            "packing.profile_step: expected at most 10000000 cuts of the profile, got 4e+12 "
            "(4 in steps of 1e-12)");
  PackingSettings cuts;
  cuts.cuts_step = 1e-12;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure(f, cuts); }),
            "packing.cuts_step: expected at most 10000000 cuts of phi_cuts, got 4e+12 (4 in "
            "steps of 1e-12)");
  // A step beyond the bed left the profile empty, exit 0.
  PackingSettings huge;
  huge.profile_step = 1e308;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure(f, huge); }),
            "packing.profile_step: expected at most the bed's height in diameters (4), got "
            "1e+308: a single bin would reach past it");
  huge.profile_step = 5.0;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure(f, huge); }),
            "packing.profile_step: expected at most the bed's height in diameters (4), got 5: "
            "a single bin would reach past it");
  // Just past the limit the count read as the limit itself ("got 1e+07").
  PackingSettings barely;
  barely.cuts_step = 4.0 / 10000001.0;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure(f, barely); }),
            "packing.cuts_step: expected at most 10000000 cuts of phi_cuts, got 10000001 (4 in "
            "steps of 3.99999960000004e-07)");
  // The analyzer names them where the pipeline has them (the harness's "params"), not
  // "packing.<name>" whatever its name and place.
  const auto ctx =
      granpipe::test::make_context(granpipe::packing::schema(), {{"cuts_step", 1e-12}});
  granpipe::packing::PackingAnalyzer analyzer(*ctx);
  FrameCache cache;
  EXPECT_EQ(granpipe::test::input_error_of([&] { analyzer.consume(f, cache); }),
            "params.cuts_step: expected at most 10000000 cuts of phi_cuts, got 4e+12 (4 in "
            "steps of 1e-12)");
  // The largest counts allowed still measure.
  PackingSettings fine;
  fine.profile_step = fine.cuts_step = 1e-3;
  EXPECT_NEAR(measure(f, fine).phi_cuts, measure(f).phi, 1e-3);
}

// At 1e14 from the origin a double's spacing is 1/64 of a diameter, and the 64 of them that
// move the region's faces down counted 9 centres of 16.
TEST(Packing, PositionsRoundedToAFractionOfADiameterAreRefused) {
  Frame far = stacks({4, 4, 4, 4}, 3, 2);
  for (const double offset : {1e14, 1e6}) {
    Frame f = far;
    f.position().leftCols(2) += offset;
    f.container.lo.head(2).array() += offset;
    f.container.hi.head(2).array() += offset;
    PackingSettings s;
    s.tolerance = 0.05;
    if (offset == 1e6) {
      EXPECT_EQ(measure(f, s).centres, 16);
      continue;
    }
    EXPECT_EQ(granpipe::test::input_error_of([&] { measure(f, s); }),
              "packing: frame at step 0: positions up to 1e+14 from the origin are rounded to "
              "0.015625: expected 64 times that (1) to be at most 0.001 of the mean diameter "
              "(0.001); move the origin into the packing");
  }
}

// A region between particle centres (the gap at the middle of four touching columns of a
// simple cubic crystal): z_mean is NaN, which was left without a word.
TEST(Packing, ARegionWithoutCentresSaysZMeanIsUndefined) {
  const auto ctx = granpipe::test::make_context(granpipe::packing::schema(),
                                                {{"exclude_sides", 1.95}, {"profile_step", 0}});
  ctx->keep_log();
  granpipe::packing::PackingAnalyzer analyzer(*ctx);
  for (int k = 0; k < 2; ++k) {
    FrameCache cache;
    analyzer.consume(one("sc", "walls"), cache);
  }
  granpipe::Results r;
  analyzer.finish(r);
  EXPECT_TRUE(std::isnan(r.scalar("z_mean").value));
  EXPECT_TRUE(std::isnan(r.tables().at("per_frame").column("z_mean")[1]));
  const std::vector<std::string> lines = ctx->logged_lines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0],
            "warning: packing: frame at step 0: no particle centred in the region: its z_mean is "
            "undefined (NaN in per_frame, left out of the mean); said for the first such frame "
            "only");
}

// Frames of Monte Carlo moves leave gaps: z_mean 0 at the default tolerance was averaged
// with a deposition's without a word. Two spheres a tenth of a radius apart: said once.
TEST(Packing, AFrameWithoutATouchingPairSaysZMeanIsZero) {
  const auto ctx = granpipe::test::make_context(granpipe::packing::schema(), {{"profile_step", 0}});
  ctx->keep_log();
  granpipe::packing::PackingAnalyzer analyzer(*ctx);
  Frame f;
  f.resize(2, 3);
  f.radius().setConstant(1.0);
  f.position().row(0) << 2.0, 2.0, 1.0;
  f.position().row(1) << 4.1, 2.0, 1.0;
  f.container =
      granpipe::Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(6, 6, 6));
  for (int k = 0; k < 2; ++k) {
    FrameCache cache;
    f.step = k;
    analyzer.consume(f, cache);
  }
  granpipe::Results r;
  analyzer.finish(r);
  EXPECT_EQ(r.scalar("z_mean").value, 0.0);
  EXPECT_EQ(ctx->logged_lines(),
            std::vector<std::string>{
                "warning: packing: frame at step 0: no two particles touch within "
                "contact_tolerance 1e-09: its z_mean is 0 (packings of Monte Carlo moves leave "
                "gaps; a larger contact_tolerance counts near contacts); said for the first such "
                "frame only"});
}
