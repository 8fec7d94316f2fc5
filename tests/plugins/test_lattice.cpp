// The lattice source: site geometry checked by brute force (every pair, minimum image),
// packing fractions against their closed forms, boxes, and reproducible jitter.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "granpipe/errors.hpp"
#include "granpipe/overlap.hpp"
#include "lattice_source.hpp"
#include "plugin_harness.hpp"

namespace {

using granpipe::Frame;
using granpipe::lattice::LatticeSource;

constexpr double kPi = std::numbers::pi;

struct Expected {
  std::string name;
  int dim;
  double phi;
  int z;
  int basis;
};

const std::vector<Expected>& lattices() {
  static const std::vector<Expected> all{
      {"square", 2, kPi / 4, 4, 1},
      {"triangular", 2, kPi / (2 * std::sqrt(3.0)), 6, 2},
      {"sc", 3, kPi / 6, 6, 1},
      {"bcc", 3, kPi * std::sqrt(3.0) / 8, 8, 2},
      {"fcc", 3, kPi / (3 * std::sqrt(2.0)), 12, 4},
      {"hcp", 3, kPi / (3 * std::sqrt(2.0)), 12, 4},
  };
  return all;
}

// Builds the source as a pipeline would, with `set` on the schema's defaults, and returns
// its frames.
std::vector<Frame> run(const nlohmann::json& set, std::uint64_t seed = 1) {
  const auto ctx = granpipe::test::make_context(granpipe::lattice::schema(), set, seed);
  LatticeSource source(*ctx);
  std::vector<Frame> frames;
  Frame f;
  while (source.next(f)) {
    f.check("lattice test");
    frames.push_back(f);
  }
  return frames;
}

// Minimum-image distance between particles i and j.
double distance(const Frame& f, Eigen::Index i, Eigen::Index j) {
  double r2 = 0;
  for (int a = 0; a < f.dim; ++a) {
    double d = f.position()(j, a) - f.position()(i, a);
    if (f.container.periodic(a)) d -= f.container.length(a) * std::round(d / f.container.length(a));
    r2 += d * d;
  }
  return std::sqrt(r2);
}

TEST(Lattice, PeriodicBoxHoldsTheClosedFormPackingFraction) {
  for (const auto& e : lattices()) {
    const Frame f = run({{"lattice", e.name}, {"radius", 0.7}}).at(0);
    ASSERT_EQ(f.dim, e.dim) << e.name;
    EXPECT_EQ(f.size(), e.basis * (e.dim == 2 ? 16 : 64)) << e.name;
    double box = 1;
    for (int a = 0; a < e.dim; ++a) {
      EXPECT_TRUE(f.container.periodic(a));
      box *= f.container.length(a);
    }
    const double phi = f.size() * granpipe::overlap::ball_measure(e.dim, 0.7) / box;
    EXPECT_NEAR(phi, e.phi, 1e-13 * e.phi) << e.name;
  }
}

// Every particle has exactly z neighbours at contact distance and none closer, counted
// over all pairs with the minimum image.
TEST(Lattice, NeighboursTouchExactly) {
  for (const auto& e : lattices()) {
    for (const std::string boundary : {"periodic", "walls"}) {
      const Frame f = run({{"lattice", e.name}, {"boundary", boundary}}).at(0);
      const double contact = 2 * 0.5;
      int max_z = 0;
      for (Eigen::Index i = 0; i < f.size(); ++i) {
        int z = 0;
        for (Eigen::Index j = 0; j < f.size(); ++j) {
          if (i == j) continue;
          const double d = distance(f, i, j);
          ASSERT_GT(d, contact * (1 - 1e-12)) << e.name << " " << boundary;
          if (d < contact * (1 + 1e-12)) ++z;
        }
        if (boundary == "periodic") {
          ASSERT_EQ(z, e.z) << e.name << " particle " << i;
        }
        max_z = std::max(max_z, z);
      }
      EXPECT_EQ(max_z, e.z) << e.name << " " << boundary;
    }
  }
}

TEST(Lattice, WallsBoxIsTightAndOpenAtTheTop) {
  for (const auto& e : lattices()) {
    const Frame f = run({{"lattice", e.name}, {"boundary", "walls"}, {"radius", 1.5}}).at(0);
    const auto& c = f.container;
    const int v = e.dim - 1;
    EXPECT_EQ(c.boundary[v][1], granpipe::Boundary::Open) << e.name;
    EXPECT_EQ(c.boundary[v][0], granpipe::Boundary::Wall) << e.name;
    for (int a = 0; a < e.dim; ++a) {
      const double low = (f.position().col(a) - f.radius()).minCoeff();
      const double high = (f.position().col(a) + f.radius()).maxCoeff();
      EXPECT_NEAR(low, c.lo[a], 1e-12) << e.name << " axis " << a;
      EXPECT_NEAR(high, c.hi[a], 1e-12) << e.name << " axis " << a;
    }
  }
}

TEST(Lattice, CellsMustMatchTheDimension) {
  EXPECT_EQ(granpipe::test::input_error_of([] {
              run({{"lattice", std::string("fcc")}, {"cells", std::vector<std::int64_t>{4, 4}}});
            }),
            "params.cells: expected 3 entries (one per axis of the 3D fcc lattice), got 2");
  EXPECT_THROW(
      run({{"lattice", std::string("square")}, {"cells", std::vector<std::int64_t>{2, 2, 2}}}),
      granpipe::InputError);
  const Frame f =
      run({{"lattice", std::string("hcp")}, {"cells", std::vector<std::int64_t>{2, 3, 5}}}).at(0);
  EXPECT_EQ(f.size(), 4 * 2 * 3 * 5);
}

// The size is estimated from the cells before the frame is allocated (10^15 particles
// was a std::bad_alloc, exit 1).
TEST(Lattice, TooManyParticlesAreRefusedBeforeAllocating) {
  EXPECT_EQ(granpipe::test::input_error_of([] {
              run({{"lattice", std::string("fcc")},
                   {"cells", std::vector<std::int64_t>{100000, 100000, 100000}}});
            }),
            "params.cells: expected at most 1e+07 particles (4 per cell), got 4e+15");
  EXPECT_THROW(
      run({{"lattice", std::string("sc")}, {"cells", std::vector<std::int64_t>{216, 216, 216}}}),
      granpipe::InputError);
}

TEST(Lattice, JitteredFramesNeverOverlap) {
  for (const std::string name : {"triangular", "fcc", "bcc"}) {
    for (const std::string boundary : {"periodic", "walls"}) {
      const auto frames = run({{"lattice", name},
                               {"boundary", boundary},
                               {"jitter", 0.4},
                               {"frames", std::int64_t{3}}});
      ASSERT_EQ(frames.size(), 3u);
      for (const Frame& f : frames) {
        EXPECT_DOUBLE_EQ(f.radius()[0], 0.5 * 0.6);
        double closest = 1e300;
        for (Eigen::Index i = 0; i < f.size(); ++i)
          for (Eigen::Index j = i + 1; j < f.size(); ++j)
            closest = std::min(closest, distance(f, i, j) - f.radius()[i] - f.radius()[j]);
        EXPECT_GT(closest, 0.0) << name << " " << boundary;
        EXPECT_LT(closest, 0.4) << name << " " << boundary;  // still a dense packing
        for (int a = 0; a < f.dim; ++a) {
          const auto& c = f.container;
          for (Eigen::Index i = 0; i < f.size(); ++i) {
            if (c.periodic(a)) {
              EXPECT_GE(f.position()(i, a), c.lo[a]);
              EXPECT_LT(f.position()(i, a), c.hi[a]);
            } else {
              EXPECT_GE(f.position()(i, a) - f.radius()[i], c.lo[a]);
              EXPECT_LE(f.position()(i, a) + f.radius()[i], c.hi[a]);
            }
          }
        }
      }
      EXPECT_FALSE(frames[0].position().isApprox(frames[1].position()));
    }
  }
}

TEST(Lattice, SameSeedSameFramesOtherSeedOtherFrames) {
  const nlohmann::json p{{"lattice", "hcp"}, {"jitter", 0.2}, {"frames", 2}};
  const auto a = run(p, 42), b = run(p, 42), c = run(p, 43);
  for (int k = 0; k < 2; ++k) {
    EXPECT_TRUE((a[k].position() == b[k].position()).all());
    EXPECT_FALSE((a[k].position() == c[k].position()).all());
    EXPECT_EQ(a[k].step, k);
    EXPECT_EQ(a[k].time, k);
    EXPECT_EQ(a[k].id()[5], 5);
    EXPECT_EQ(a[k].species()[5], 0);
  }
  // Without jitter the seed plays no part.
  const auto d = run({{"lattice", std::string("hcp")}}, 1),
             e = run({{"lattice", std::string("hcp")}}, 2);
  EXPECT_TRUE((d[0].position() == e[0].position()).all());
}

}  // namespace

// 1e12 frames ran on, writing 10 MB/s, with an ETA of 300 000 hours.
TEST(Lattice, MoreThan1e8FramesAreRefused) {
  EXPECT_EQ(granpipe::test::input_error_of([] {
              run({{"frames", std::int64_t{1000000000000}}});
            }),
            "test: params.frames: expected an integer in [1, 100000000], got 1000000000000");
}
