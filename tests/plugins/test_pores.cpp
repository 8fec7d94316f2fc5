// The pores analyzer on crystals built here: the exact pore sizes and counts per sphere of
// fcc, hcp, sc and bcc (degenerate sites merged into one pore, whatever the triangulation's
// tie-breaking), the same counts after a jitter far below the tolerance, Bernal's holes,
// the region, and the inputs refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "bernal_holes.hpp"
#include "crystals.hpp"
#include "granpipe/errors.hpp"
#include "measure_pores.hpp"
#include "plugin_harness.hpp"
#include "pore_region.hpp"
#include "pore_statistics.hpp"
#include "volume_distribution.hpp"

namespace {

using granpipe::Frame;
using granpipe::InputError;
using granpipe::Region;
using granpipe::pores::measure_pores;
using granpipe::pores::PoreMeasurement;
using granpipe::test::bcc;
using granpipe::test::Crystal;
using granpipe::test::crystal_frame;
using granpipe::test::fcc;
using granpipe::test::hcp;
using granpipe::test::sc;

const double kTetrahedral = std::sqrt(1.5) - 1.0;
const double kOctahedral = std::sqrt(2.0) - 1.0;

// Unit cells `from` to `to` of the crystal, shifted by a tenth of a cell so that no
// particle and no pore lies on its sides: it holds whole cells' worth of each.
Region inner_cells(const Crystal& c, int from, int to, double radius = 1.0) {
  Region r;
  for (int a = 0; a < 3; ++a) {
    r.lo[a] = radius * c.cell[a] * (from + 0.1);
    r.hi[a] = radius * c.cell[a] * (to + 0.1);
  }
  return r;
}

long count_near(const std::vector<double>& xi, double value, double tolerance) {
  return std::count_if(xi.begin(), xi.end(),
                       [&](double x) { return std::abs(x - value) <= tolerance; });
}

struct Kind {
  double xi;
  long per_sphere;
};

// Every pore is of one of the kinds, in the given numbers per sphere, to 1e-9.
void expect_kinds(const PoreMeasurement& m, const std::vector<Kind>& kinds,
                  const std::string& name) {
  ASSERT_GT(m.spheres, 0) << name;
  long all = 0;
  for (const Kind& k : kinds) {
    EXPECT_EQ(count_near(m.xi, k.xi, 1e-9), k.per_sphere * m.spheres) << name << " xi " << k.xi;
    all += k.per_sphere * m.spheres;
  }
  EXPECT_EQ(static_cast<long>(m.xi.size()), all) << name;
}

PoreMeasurement inner(const Crystal& c, int cells, const Frame& f) {
  return measure_pores(f, inner_cells(c, 2, cells - 2, f.radius()[0]), 1e-9, "test");
}

TEST(Pores, FccHasTetrahedralAndOctahedralSites) {
  for (double radius : {1e-3, 1.0, 1e3}) {
    const Frame f = crystal_frame(fcc(), 6, radius);
    const PoreMeasurement m = inner(fcc(), 6, f);
    EXPECT_EQ(m.spheres, 4 * 8);
    expect_kinds(m, {{kTetrahedral, 2}, {kOctahedral, 1}}, "fcc radius " + std::to_string(radius));
  }
}

TEST(Pores, HcpHasTheSameSitesAsFcc) {
  const Frame f = crystal_frame(hcp(), 6);
  const PoreMeasurement m = inner(hcp(), 6, f);
  EXPECT_EQ(m.spheres, 4 * 8);
  expect_kinds(m, {{kTetrahedral, 2}, {kOctahedral, 1}}, "hcp");
}

TEST(Pores, SimpleCubicHasOneCubicSitePerSphere) {
  const PoreMeasurement m = inner(sc(), 7, crystal_frame(sc(), 7));
  EXPECT_EQ(m.spheres, 27);
  expect_kinds(m, {{std::sqrt(3.0) - 1.0, 1}}, "sc");
}

// BCC's Delaunay cells are tetrahedra with two corners on a cube edge and two at the
// centres of the cubes beside it: circumradius sqrt(5)/4 a with a = 4R/sqrt(3), so
// xi = sqrt(5/3) - 1, six per sphere (the 24 vertices of the truncated octahedron, each
// shared by four cells).
TEST(Pores, BccHasSixDistortedTetrahedralSitesPerSphere) {
  const PoreMeasurement m = inner(bcc(), 6, crystal_frame(bcc(), 6));
  EXPECT_EQ(m.spheres, 2 * 8);
  expect_kinds(m, {{std::sqrt(5.0 / 3.0) - 1.0, 6}}, "bcc");
}

// A periodic box of whole cells: every sphere and every pore once, also those exactly on
// the box's sides, wherever the crystal sits in the box.
TEST(Pores, PeriodicCrystalsCountEachPoreOnce) {
  const std::vector<std::pair<Crystal, std::vector<Kind>>> crystals{
      {fcc(), {{kTetrahedral, 2}, {kOctahedral, 1}}},
      {hcp(), {{kTetrahedral, 2}, {kOctahedral, 1}}},
      {sc(), {{std::sqrt(3.0) - 1.0, 1}}},
      {bcc(), {{std::sqrt(5.0 / 3.0) - 1.0, 6}}}};
  for (const auto& [c, kinds] : crystals) {
    for (double offset : {0.0, 0.37}) {
      Frame f = crystal_frame(c, 3);
      f.container = granpipe::Container::periodic_box(3, {0, 0, 0}, 3 * c.cell);
      f.position().rowwise() += offset * c.cell.transpose().array();
      const PoreMeasurement m = measure_pores(f, std::nullopt, 1e-9, "test");
      EXPECT_EQ(m.spheres, f.size());
      expect_kinds(m, kinds, "periodic, offset " + std::to_string(offset));
    }
  }
}

// Periodic sides and an open top with a bumpy surface (two spheres sitting on the top
// layer, far apart): the cells above the surface are far wider than the box, and a region
// below the top does not need them; before, the whole frame was refused for them.
TEST(Pores, PeriodicSidesWithAnOpenTopCountTheRegionBelowIt) {
  const Crystal c = sc();
  const int cells = 6, layers = 4;
  Frame layered = crystal_frame(c, cells);
  Frame f;
  f.resize(static_cast<Eigen::Index>(cells * cells * layers + 2), 3);
  f.radius().setConstant(1.0);
  Eigen::Index k = 0;
  for (Eigen::Index i = 0; i < layered.size(); ++i) {
    if (layered.position()(i, 2) < 2.0 * layers) f.position().row(k++) = layered.position().row(i);
  }
  ASSERT_EQ(k, cells * cells * layers);
  const double top = 2.0 * (layers - 1);                    // the top layer's centres
  f.position().row(k++) << 1.0, 1.0, top + std::sqrt(2.0);  // in the hollow of four
  f.position().row(k++) << 7.0, 5.0, top + std::sqrt(2.0);
  f.container = granpipe::Container::periodic_box(3, {-1, -1, -1}, {11, 11, 30});
  f.container.boundary[2] = {granpipe::Boundary::Wall, granpipe::Boundary::Open};
  Region below;
  below.lo = Eigen::Vector3d(-1, -1, 0.5);
  below.hi = Eigen::Vector3d(11, 11, top - 0.5);
  const PoreMeasurement m = measure_pores(f, below, 1e-9, "test");
  // The cubes between layers 0-1, 1-2 and 2-3: 6 x 6 each, centred below top - 1.
  EXPECT_EQ(m.xi.size(), static_cast<std::size_t>(cells * cells * (layers - 1)));
  for (double xi : m.xi) EXPECT_NEAR(xi, std::sqrt(3.0) - 1.0, 1e-9);
  // Region all counts up to the surface (the outermost particle top): the cubes, and the
  // hollows of the top layer under the two spheres in them, none of the cells above.
  const auto all =
      granpipe::pores::pore_region(f, {granpipe::pores::RegionKind::All, 2.0, 0.0}, 1.0, "test");
  const PoreMeasurement counted = measure_pores(f, all, 1e-9, "test");
  EXPECT_GE(counted.xi.size(), static_cast<std::size_t>(cells * cells * (layers - 1)));
  for (double xi : counted.xi) EXPECT_TRUE(std::isfinite(xi));
}

TEST(Pores, FourTouchingSpheresMakeOneTetrahedralPore) {
  Frame f;
  f.resize(4, 3);
  f.radius().setConstant(0.5);
  const double s = 1.0 / std::sqrt(2.0);  // the corners of a cube alternately: edge 1
  f.position() << s, s, s, s, -s, -s, -s, s, -s, -s, -s, s;
  f.position() *= 0.5;
  f.container.lo.setConstant(-2);
  f.container.hi.setConstant(2);
  const PoreMeasurement m = measure_pores(f, std::nullopt, 1e-9, "test");
  ASSERT_EQ(m.xi.size(), 1u);
  EXPECT_NEAR(m.xi[0], kTetrahedral, 1e-12);
  EXPECT_EQ(m.spheres, 4);
}

// The same crystal with its particles in another order: the triangulation splits the
// degenerate sites otherwise, the pores are the same.
TEST(Pores, CountsDoNotDependOnTheTriangulationsTieBreaking) {
  for (const Crystal& c : {fcc(), sc()}) {
    const Frame f = crystal_frame(c, 6);
    Frame shuffled = f;
    std::vector<Eigen::Index> order(static_cast<std::size_t>(f.size()));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(5));
    for (Eigen::Index k = 0; k < f.size(); ++k)
      shuffled.position().row(k) = f.position().row(order[static_cast<std::size_t>(k)]);
    const PoreMeasurement a = inner(c, 6, f), b = inner(c, 6, shuffled);
    ASSERT_EQ(a.xi.size(), b.xi.size());
    std::vector<double> xa = a.xi, xb = b.xi;
    std::sort(xa.begin(), xa.end());
    std::sort(xb.begin(), xb.end());
    for (std::size_t k = 0; k < xa.size(); ++k) EXPECT_NEAR(xa[k], xb[k], 1e-12);
  }
}

// Displacements of 1e-12 R make the degenerate sites non-degenerate, split them into
// cells of slightly different spheres and add slivers: none of it is a new pore.
TEST(Pores, AJitterBelowTheToleranceChangesNoCount) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> shift(-1e-12, 1e-12);
  struct Case {
    Crystal crystal;
    std::vector<Kind> kinds;
    bool degenerate;  // sites of more than four cospherical particles
  };
  const std::vector<Case> cases{{fcc(), {{kTetrahedral, 2}, {kOctahedral, 1}}, true},
                                {sc(), {{std::sqrt(3.0) - 1.0, 1}}, true},
                                {bcc(), {{std::sqrt(5.0 / 3.0) - 1.0, 6}}, false}};
  for (const auto& [c, kinds, degenerate] : cases) {
    Frame f = crystal_frame(c, 6);
    for (Eigen::Index k = 0; k < f.size(); ++k)
      for (int a = 0; a < 3; ++a) f.position()(k, a) += shift(rng);
    const std::size_t merged = inner(c, 6, f).xi.size();
    expect_kinds(inner(c, 6, f), kinds, "jittered");
    // A tolerance below the jitter sees the pieces of the split sites as pores.
    const std::size_t resolved = measure_pores(f, inner_cells(c, 2, 4), 1e-14, "test").xi.size();
    if (degenerate) {
      EXPECT_GT(resolved, merged);
    } else {
      EXPECT_EQ(resolved, merged);
    }
  }
}

// Region "all" in a walled container counted the slivers of the convex hull along the walls,
// whose centres lie far outside (below the base): a jittered FCC block gave nu = 1.6e27
// with exit 0. The pores of the container are those of the crystal and its faces.
TEST(Pores, RegionAllCountsThePoresOfTheContainerOnly) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> shift(-1e-9, 1e-9);
  Frame f = crystal_frame(fcc(), 4);
  const auto all =
      granpipe::pores::pore_region(f, {granpipe::pores::RegionKind::All, 2.0, 0.0}, 1.0, "test");
  const PoreMeasurement perfect = measure_pores(f, all, 1e-9, "test");
  for (Eigen::Index k = 0; k < f.size(); ++k)
    for (int a = 0; a < 3; ++a) f.position()(k, a) += shift(rng);
  const PoreMeasurement jittered = measure_pores(f, all, 1e-6, "test");
  ASSERT_FALSE(perfect.xi.empty());
  EXPECT_EQ(jittered.xi.size(), perfect.xi.size());
  EXPECT_LE(*std::max_element(jittered.xi.begin(), jittered.xi.end()), std::sqrt(2.0) - 1.0 + 1e-6);
}

TEST(Pores, FccPoresAreTwoThirdsTetrahedraByNumber) {
  granpipe::pores::PoreStatistics stats(0.01, 1.0);
  stats.add(inner(fcc(), 6, crystal_frame(fcc(), 6)));
  const auto& counts = stats.hole_counts();
  EXPECT_EQ(counts[0], 64);  // tetrahedra
  EXPECT_EQ(counts[2], 32);  // octahedra
  EXPECT_EQ(stats.pores(), 96);
  const double t3 = std::pow(kTetrahedral, 3), o3 = std::pow(kOctahedral, 3);
  EXPECT_NEAR(stats.nu(), (2 * t3 + o3) / 3, 1e-12);
  EXPECT_NEAR(stats.hole_volumes()[2] / (64 * t3 + 32 * o3), o3 / (2 * t3 + o3), 1e-12);
  const auto& bins = stats.counts();
  EXPECT_EQ(bins[static_cast<std::size_t>(kTetrahedral / 0.01)], 64);
  EXPECT_EQ(bins[static_cast<std::size_t>(kOctahedral / 0.01)], 32);
}

TEST(Pores, PoresAreNearTheirCanonicalHole) {
  using granpipe::pores::nearest_hole;
  EXPECT_EQ(nearest_hole(kTetrahedral), 0u);
  EXPECT_EQ(nearest_hole(0.36), 1u);
  EXPECT_EQ(nearest_hole(kOctahedral), 2u);
  EXPECT_EQ(nearest_hole(std::sqrt(7.0 / 3.0) - 1.0), 3u);  // the regular trigonal prism
  EXPECT_EQ(nearest_hole(0.65), 4u);
  EXPECT_EQ(nearest_hole(0.1), 5u);  // overlapping spheres
  EXPECT_EQ(nearest_hole(0.9), 5u);  // near a wall or the free surface
}

TEST(Pores, InnerRegionKeepsItsMarginFromTheWalls) {
  Frame f = crystal_frame(sc(), 5);  // centres 0..8, walls at -1 and 9
  granpipe::pores::RegionSettings s{granpipe::pores::RegionKind::Inner, 2.0, 3.0};
  const auto r = granpipe::pores::pore_region(f, s, 1.0, "test");
  ASSERT_TRUE(r);
  EXPECT_DOUBLE_EQ(r->box.lo[0], 1.0);
  EXPECT_DOUBLE_EQ(r->box.hi[1], 7.0);
  EXPECT_DOUBLE_EQ(r->box.lo[2], 1.0);
  EXPECT_DOUBLE_EQ(r->box.hi[2], 4.0);
  s.height = 8.0;  // above the top of the packing
  EXPECT_THROW(granpipe::pores::pore_region(f, s, 1.0, "test"), InputError);
  // "all": the container itself (the hull's slivers have their centres far outside it).
  s = {granpipe::pores::RegionKind::All, 2.0, 0.0};
  const auto all = granpipe::pores::pore_region(f, s, 1.0, "test");
  ASSERT_TRUE(all);
  EXPECT_DOUBLE_EQ(all->box.lo[0], -1.0);
  EXPECT_DOUBLE_EQ(all->box.hi[1], 9.0);
  EXPECT_DOUBLE_EQ(all->box.lo[2], -1.0);
}

// An SC lattice's pores lie on the inner region's faces at the default margin: counted on
// one side (the half-open box, moved down by half the tolerance), whatever the rounding of
// their centres. Before, 64 pores with radius 0.5, 125 with 0.05, 27 moved by 0.1.
TEST(Pores, PoresOnTheInnerRegionsFacesAreCountedOnOneSide) {
  for (const double radius : {0.5, 0.05, 1.5}) {
    for (const double moved : {0.0, 0.1, 1e3}) {
      Frame f = crystal_frame(sc(), 6, radius);  // pores at (2i + 1) R, faces at R and 9 R
      f.position().array() += moved;
      f.container.lo.array() += moved;
      f.container.hi.array() += moved;
      const granpipe::pores::RegionSettings s{granpipe::pores::RegionKind::Inner, 2.0, 0.0};
      const PoreMeasurement m =
          measure_pores(f, granpipe::pores::pore_region(f, s, radius, "test"), 1e-9, "test");
      EXPECT_EQ(m.xi.size(), 64u) << "radius " << radius << ", moved by " << moved;
      EXPECT_EQ(m.spheres, 64) << "radius " << radius << ", moved by " << moved;
    }
  }
}

// Periodic on every side, a margin of 100 radii changed nothing (exit 0): no wall to keep
// it from.
TEST(Pores, AnInnerRegionNeedsAWall) {
  Frame f = crystal_frame(sc(), 5);
  for (auto& sides : f.container.boundary)
    sides = {granpipe::Boundary::Periodic, granpipe::Boundary::Periodic};
  granpipe::pores::RegionSettings s{granpipe::pores::RegionKind::Inner, 100.0, 0.0};
  EXPECT_EQ(
      granpipe::test::input_error_of([&] { granpipe::pores::pore_region(f, s, 1.0, "test"); }),
      "test: expected region \"all\" for a container periodic on every side (an inner "
      "region keeps its margin from walls, and it has none), got \"inner\"");
}

// In a vertical cylinder the inner region also keeps its margin from the curved wall
// (wherever the moving walls have carried the axis): the Brazil-nut frames' pores at the
// cylinder, open to the wall, gave a mean pore volume of 5e18 with region "all".
TEST(Pores, InnerRegionInACylinderKeepsItsMarginFromTheCurvedWall) {
  Frame f = crystal_frame(sc(), 5);  // centres 0..8
  f.container.shape = granpipe::ContainerShape::Cylinder;
  f.container.cylinder_center = {4.0, 4.0};
  f.container.cylinder_radius = 6.0;
  f.container.wall_offset = {0.5, 0.0, 0.0};
  granpipe::pores::RegionSettings s{granpipe::pores::RegionKind::Inner, 2.0, 0.0};
  const auto r = granpipe::pores::pore_region(f, s, 1.0, "test");
  ASSERT_TRUE(r);
  EXPECT_DOUBLE_EQ(r->radius, 4.0);
  EXPECT_TRUE(r->contains({4.5 + 2.9, 4.0, 3.0}));
  EXPECT_TRUE(r->contains({4.5 + 2.8, 4.0 + 2.8, 3.0}));   // 3.96 from the axis
  EXPECT_FALSE(r->contains({4.5 + 2.9, 4.0 + 2.9, 3.0}));  // in the box, 4.1 from the axis
  s.margin = 6.0;
  EXPECT_THROW(granpipe::pores::pore_region(f, s, 1.0, "test"), InputError);
}

// The analyzer as a pipeline runs it.
TEST(Pores, AnalyzerPoolsFrames) {
  const auto ctx = granpipe::test::make_context("pores", {{"region", "inner"}, {"margin", 3.0}});
  auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(*ctx);
  const Frame f = crystal_frame(fcc(), 5);
  granpipe::FrameCache cache;
  analyzer->consume(f, cache);
  analyzer->consume(f, cache);
  granpipe::Results results;
  analyzer->finish(results);
  EXPECT_EQ(results.scalar("frames").value, 2);
  const double pores = results.scalar("pores").value;
  EXPECT_GT(pores, 0);
  const auto& counts = results.tables().at("bernal").column("count");
  EXPECT_EQ(counts[0] + counts[2], pores);  // tetrahedra and octahedra only
  EXPECT_EQ(results.tables().at("per_frame").rows(), 2u);
}

// frame_distributions: each frame's P(xi) and rho_v(v), which for one frame are the pooled
// ones; here two frames of a crystal, so both frames' rows equal the pooled table.
TEST(Pores, FrameDistributionsAreEachFramesOwn) {
  const auto ctx = granpipe::test::make_context(
      "pores", {{"region", "inner"}, {"margin", 3.0}, {"frame_distributions", true}});
  auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(*ctx);
  const Frame f = crystal_frame(fcc(), 5);
  granpipe::FrameCache cache;
  analyzer->consume(f, cache);
  analyzer->consume(f, cache);
  granpipe::Results results;
  analyzer->finish(results);
  const granpipe::Table& pooled = results.tables().at("xi_distribution");
  const granpipe::Table& per_frame = results.tables().at("frame_xi");
  ASSERT_EQ(per_frame.rows(), 2 * pooled.rows());
  for (std::size_t k = 0; k < per_frame.rows(); ++k) {
    EXPECT_EQ(per_frame.column("P")[k], pooled.column("P")[k % pooled.rows()]) << k;
  }
  const granpipe::Table& volumes = results.tables().at("volume_distribution");
  ASSERT_EQ(results.tables().at("frame_v").rows(), 2 * volumes.rows());
  EXPECT_EQ(results.tables().at("frame_v").column("rho_v")[3], volumes.column("rho_v")[3]);
}

// pore_table: a row per pore, merged sites one row. A periodic fcc crystal has per sphere
// two tetrahedral pores of one Delaunay cell each and one octahedral pore, a regular
// octahedron, which any triangulation splits into four cells around a diagonal. With it the
// published columns: every cell the rhombic dodecahedron, 4 sqrt 2 R^3, at a packing
// fraction pi / (3 sqrt 2).
TEST(Pores, PoreTableListsEachPoreWithItsCells) {
  const auto ctx = granpipe::test::make_context("pores", {{"pore_table", true}});
  auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(*ctx);
  Frame f = crystal_frame(fcc(), 3);
  f.container = granpipe::Container::periodic_box(3, {0, 0, 0}, 3 * fcc().cell);
  granpipe::FrameCache cache;
  analyzer->consume(f, cache);
  granpipe::PropertyTable columns(granpipe::Scope::Particle, f.size());
  for (const auto& p : analyzer->publishes()) columns.add(p);
  analyzer->publish(columns);
  granpipe::Results results;
  analyzer->finish(results);
  const granpipe::Table& t = results.tables().at("pore_table");
  ASSERT_EQ(t.rows(), static_cast<std::size_t>(3 * f.size()));
  long tetrahedral = 0, octahedral = 0;
  for (std::size_t k = 0; k < t.rows(); ++k) {
    const double xi = t.column("xi")[k], cells = t.column("cells")[k];
    tetrahedral += std::abs(xi - kTetrahedral) < 1e-9 && cells == 1;
    octahedral += std::abs(xi - kOctahedral) < 1e-9 && cells == 4;
    EXPECT_EQ(t.column("in_region")[k], 1.0);
    EXPECT_EQ(t.column("frame")[k], 0.0);
  }
  EXPECT_EQ(tetrahedral, 2 * f.size());
  EXPECT_EQ(octahedral, f.size());
  EXPECT_EQ(results.scalar("undefined_volumes").value, 0);
  const auto& volume = columns.get<Eigen::ArrayXd>("voronoi_volume");
  const auto& fraction = columns.get<Eigen::ArrayXd>("local_packing_fraction");
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    EXPECT_NEAR(volume[k], 4.0 * std::sqrt(2.0), 1e-9) << k;
    EXPECT_NEAR(fraction[k], M_PI / (3.0 * std::sqrt(2.0)), 1e-9) << k;
  }
}

// Without pore_table no table; the columns are published all the same.
TEST(Pores, PoreTableIsLeftOutByDefault) {
  const auto ctx = granpipe::test::make_context("pores", {});
  auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(*ctx);
  granpipe::FrameCache cache;
  analyzer->consume(crystal_frame(sc(), 3), cache);
  granpipe::Results results;
  analyzer->finish(results);
  EXPECT_EQ(results.tables().count("pore_table"), 0u);
  EXPECT_EQ(analyzer->publishes().size(), 2u);
}

std::string refusal(const Frame& f) {
  try {
    measure_pores(f, std::nullopt, 1e-9, "test");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

Frame square_layer() {  // 3 x 3 centres in the plane z = 0
  Frame f;
  f.resize(9, 3);
  f.radius().setConstant(1.0);
  for (Eigen::Index k = 0; k < 9; ++k) f.position().row(k) << 2.0 * (k % 3), 2.0 * (k / 3), 0.0;
  f.container.lo.setConstant(-1);
  f.container.hi.setConstant(5);
  return f;
}

TEST(Pores, BadInputIsRefusedWithOneLine) {
  Frame f = crystal_frame(sc(), 2);
  EXPECT_EQ(refusal(f), "accepted");

  Frame three = f;
  three.resize(3, 3);  // at the origin, of radius 0
  three.radius().setConstant(1.0);
  three.position().col(0) << 0, 2, 4;
  EXPECT_NE(refusal(three).find("expected at least 4 particles"), std::string::npos);

  Frame duplicate = f;
  duplicate.position().row(5) = duplicate.position().row(2);
  EXPECT_NE(refusal(duplicate).find("particles 2 and 5 at one position"), std::string::npos)
      << refusal(duplicate);

  // 10^-12 R apart: a particle given twice with rounding, counted as two spheres (exit 0).
  Frame near = f;
  near.position().row(5) = near.position().row(2);
  near.position()(5, 0) += 1e-12;
  EXPECT_NE(refusal(near).find("particles 2 and 5 1e-12 apart, closer than tolerance times the "
                               "mean radius (1e-09), by which pores are told apart"),
            std::string::npos)
      << refusal(near);

  EXPECT_NE(refusal(square_layer()).find("in one plane"), std::string::npos);
  Frame line = square_layer();
  line.position().col(1).setZero();
  line.position().col(0) = Eigen::ArrayXd::LinSpaced(9, 0, 16);
  EXPECT_NE(refusal(line).find("on one line"), std::string::npos) << refusal(line);

  Frame nan = f;
  nan.position()(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(refusal(nan), "accepted");

  Frame tiny;  // a periodic slab far thinner than the pores between its spheres
  tiny.resize(4, 3);
  tiny.radius().setConstant(0.1);
  tiny.position() << 0.2, 10, 10, 0.5, 20, 10, 0.7, 10, 30, 0.3, 40, 40;
  tiny.container = granpipe::Container::periodic_box(3, {0, 0, 0}, {1, 100, 100});
  EXPECT_NE(refusal(tiny).find("expected periodic sides longer than the pores"), std::string::npos)
      << refusal(tiny);

  for (const std::string& message : {refusal(three), refusal(duplicate), refusal(nan)}) {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// The pores analyzer took 80 random spheres overlapping by up to their radii for a packing:
// pores inside spheres, local packing fractions up to 338, exit 0. Soft-sphere overlaps of a
// few percent are pores' to measure; deeper ones are refused, naming the pair.
TEST(Pores, SpheresOverlappingBeyondMaxOverlapAreRefused) {
  const auto refused = [](const Frame& f, const nlohmann::json& params) -> std::string {
    const auto ctx = granpipe::test::make_context("pores", params);
    auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(*ctx);
    granpipe::FrameCache cache;
    try {
      analyzer->consume(f, cache);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  const Frame f = crystal_frame(sc(), 3);  // particle 1 touches particle 0 from above
  ASSERT_EQ(f.position()(1, 2), 2.0);
  Frame soft = f;
  soft.position()(1, 2) -= 0.04;  // 4 % of the radius
  EXPECT_EQ(refused(soft, nlohmann::json::object()), "accepted");
  EXPECT_EQ(refused(soft, {{"max_overlap", 0.01}}),
            "pores: frame at step 0: particles 0 and 1 overlap by 0.04 of the smaller radius, "
            "expected at most 0.01 (params.max_overlap): pores are the void between spheres "
            "that overlap little");
  Frame deep = f;
  deep.position()(1, 2) -= 0.4;
  EXPECT_EQ(refused(deep, nlohmann::json::object()),
            "pores: frame at step 0: particles 0 and 1 overlap by 0.4 of the smaller radius, "
            "expected at most 0.05 (params.max_overlap): pores are the void between spheres "
            "that overlap little");
}

}  // namespace

// Pores whose volumes v have the number density ~ exp(-v / lambda) / v (rejection from an
// exponential): the volume-weighted rho_v is then exactly ~ exp(-v / lambda), and the tail
// fit must give lambda back; rho_v integrates to <v> = nu when every pore is in range.
TEST(PoresVolume, TailFitRecoversAnExponentialAndRhoIntegratesToNu) {
  const double lambda = 0.05, v_min = 0.01;
  std::mt19937_64 rng(17);
  std::exponential_distribution<double> exponential(1.0 / lambda);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xi;
  double v_sum = 0.0;
  while (xi.size() < 200000) {
    const double v = v_min + exponential(rng);
    if (v > 0.9 || u(rng) > v_min / v) continue;
    xi.push_back(std::cbrt(v));
    v_sum += v;
  }
  granpipe::pores::VolumeDistribution d(0.005, 1.0, 0.05);
  d.add(xi);
  const double nu = v_sum / static_cast<double>(xi.size());
  double integral = 0.0;
  for (double rho : d.density()) integral += rho * 0.005;
  EXPECT_NEAR(integral, nu, 1e-12);
  const granpipe::CurveFit fit = d.tail_fit(nu);
  ASSERT_TRUE(fit.fitted()) << granpipe::describe(fit.status);
  EXPECT_NEAR(fit.value[1], lambda, 3.0 * fit.error[1]);
  EXPECT_LT(fit.error[1], 0.05 * lambda);
}

// A bin width far too small for its range asked for 10^9 bins and more: the run stopped
// with std::bad_alloc, exit 1 (or took the machine's memory). Refused when made, as are
// more probes per frame than memory holds.
TEST(Pores, HistogramsOfMoreBinsThanMemoryHoldsAreRefused) {
  const auto message = [](const nlohmann::json& params) -> std::string {
    try {
      const auto ctx = granpipe::test::make_context("pores", params);
      granpipe::test::installed_plugins().find("pores")->make_analyzer(*ctx);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(message({{"bin_width", 1e-6}, {"xi_max", 1000}}),
            "params.bin_width: expected at most 10000000 bins up to xi_max, got "
            "1e+09 (1000 in steps of 1e-06)");
  EXPECT_EQ(message({{"v_bin_width", 1e-6}, {"v_max", 100}}),
            "params.v_bin_width: expected at most 10000000 bins up to v_max, got "
            "1e+08 (100 in steps of 1e-06)");
  EXPECT_EQ(message({{"probes", std::int64_t{1000000000000}}}),
            "test: params.probes: expected an integer in [0, 100000000], got 1000000000000");
  EXPECT_EQ(message({{"bin_width", 1e-4}, {"xi_max", 1000}}), "accepted");
  // One bin past xi_max widened the histogram to it: every pore counted below 0.001.
  EXPECT_EQ(message({{"bin_width", 1}, {"xi_max", 0.001}}),
            "params.bin_width: expected at most xi_max (0.001), got 1: a single bin would reach "
            "past it");
  EXPECT_EQ(message({{"v_bin_width", 1}, {"v_max", 0.001}}),
            "params.v_bin_width: expected at most v_max (0.001), got 1: a single bin would reach "
            "past it");
}

namespace {

// The results of the installed pores analyzer on an FCC crystal of 5^3 cells, its log kept.
granpipe::Results crystal_results(granpipe::test::PluginHarness& ctx) {
  ctx.keep_log();
  auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(ctx);
  granpipe::FrameCache cache;
  analyzer->consume(crystal_frame(fcc(), 5), cache);
  granpipe::Results results;
  analyzer->finish(results);
  return results;
}

}  // namespace

// A crystal's pores fill two bins of rho_v, the octahedral one alone from v_tail up: the
// tail fit's A and lambda were NaN without a status or a word.
TEST(Pores, AnUnfittedVolumeTailIsSaid) {
  const auto ctx = granpipe::test::make_context("pores", {});
  const granpipe::Results results = crystal_results(*ctx);
  EXPECT_EQ(results.scalar("rho_v_tail_status").value,
            static_cast<double>(granpipe::CurveFitStatus::TooFewPoints));
  EXPECT_TRUE(std::isnan(results.fits().at("rho_v_tail").values[1]));
  EXPECT_EQ(ctx->logged_lines(),
            (std::vector<std::string>{
                "warning: pores: the fit of rho_v's tail (v >= v_tail), not fitted: no more "
                "points than parameters: A and lambda are undefined (NaN)"}));
}

// An SC lattice of radius 0.05 moved 10^6 from the origin: its positions are rounded to
// 1.2e-10, above tolerance x R, and its cube sites split into several pores (170 for 125)
// without a word. Said, with a tolerance that merges them again.
TEST(Pores, PositionsCoarserThanTheToleranceAreSaid) {
  Frame f = crystal_frame(sc(), 6, 0.05);
  f.position().array() += 1e6;
  f.container.lo.array() += 1e6;
  f.container.hi.array() += 1e6;
  const auto pores_of = [&](granpipe::test::PluginHarness& ctx) {
    ctx.keep_log();
    auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(ctx);
    granpipe::FrameCache cache;
    analyzer->consume(f, cache);
    granpipe::Results results;
    analyzer->finish(results);
    return results.scalar("pores").value;
  };
  const auto coarse = granpipe::test::make_context("pores", {});
  pores_of(*coarse);
  const std::vector<std::string> lines = coarse->logged_lines();
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0],
            "warning: pores: frame at step 0: positions up to 1e+06 from the origin are "
            "rounded to 1.16415e-10, more than a quarter of tolerance x the mean radius "
            "(5e-11): pores of one site may be counted apart; raise tolerance to 1.86265e-08 "
            "or move the origin into the packing");
  const auto fine = granpipe::test::make_context("pores", {{"tolerance", 1.9e-8}});
  EXPECT_EQ(pores_of(*fine), 125.0);  // 5^3 cube sites
  for (const std::string& line : fine->logged_lines())
    EXPECT_EQ(line.find("rounded to"), std::string::npos) << line;
}

// A region that holds no pore (a thin slab between layers of pores) left every
// distribution NaN without a word, as if the packing had none.
TEST(Pores, ARegionWithoutPoresIsSaid) {
  const auto ctx = granpipe::test::make_context(
      "pores", {{"region", "inner"}, {"margin", 2.5}, {"height", 0.05}});
  const granpipe::Results results = crystal_results(*ctx);
  ASSERT_EQ(results.scalar("pores").value, 0);
  EXPECT_TRUE(std::isnan(results.scalar("nu").value));
  EXPECT_TRUE(std::isnan(results.scalar("pores_per_sphere").value));
  const std::vector<std::string> lines = ctx->logged_lines();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0],
            "warning: pores: no pore in the region of any frame: P(xi), nu, rho_v and the shares "
            "of Bernal's holes are undefined (NaN); a larger region (margin, height) holds some");
  // No sphere either: pores_per_sphere NaN went without a word.
  EXPECT_EQ(lines[1],
            "warning: pores: 1 of 1 frame(s) have no particle centre in the region: their "
            "pores_per_sphere is undefined (NaN), and so is the pooled one");
}

// Spheres centred on one large sphere (a Fibonacci spiral, about 3 R apart): every cell
// of the triangulation has that sphere as its circumsphere, so there is one pore. The
// thinnest cells' circumcentres scattered 1e-7 R (exact arithmetic on the rounded
// coordinates as well) and split it into 16 pores without a word.
TEST(Pores, ManyCosphericalSpheresMakeOnePore) {
  const int n = 5000;
  const double ring = 32.0;
  Frame f;
  f.resize(n, 3);
  f.radius().setConstant(0.5);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n;
    const double r = std::sqrt(1.0 - z * z);
    f.position().row(k) << ring * r * std::cos(golden * k), ring * r * std::sin(golden * k),
        ring * z;
  }
  f.container.lo.setConstant(-40);
  f.container.hi.setConstant(40);
  const PoreMeasurement m = measure_pores(f, std::nullopt, 1e-9, "test");
  ASSERT_EQ(m.xi.size(), 1u);
  EXPECT_EQ(m.pores[0].cells, m.cells);
  EXPECT_NEAR(m.xi[0], ring / 0.5 - 1.0, 1e-9);
}
