// The multipass MST: against a brute-force Prim on random particles, deterministic on
// lattices with ties, the paper's Fig. 13, elongation once per edge, TCPs and the columns
// it publishes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <utility>

#include "candidate_edges.hpp"
#include "components.hpp"
#include "mst_analyzer.hpp"
#include "multipass.hpp"
#include "plugin_harness.hpp"
#include "tcp_report.hpp"

using namespace granpipe;
using namespace granpipe::mst;

namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

Frame open_frame(Eigen::Index n, double side) {
  Frame f;
  f.resize(n, 3);
  f.container =
      Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(side));
  return f;
}

// n particles at uniform random positions, radii in [0.4, 0.6].
Frame random_frame(Eigen::Index n, double side, unsigned seed) {
  Frame f = open_frame(n, side);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(0.0, side), r(0.4, 0.6);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (int a = 0; a < 3; ++a) f.position()(k, a) = x(rng);
    f.radius()[k] = r(rng);
  }
  return f;
}

double distance(const Frame& f, Eigen::Index a, Eigen::Index b) {
  return (f.position().row(a) - f.position().row(b)).matrix().norm();
}

// O(N^2) Prim on the complete graph: the MST's edges (i < j) and weight.
std::pair<std::set<Pair>, double> prim(const Frame& f) {
  const Eigen::Index n = f.size();
  std::vector<double> best(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  std::vector<Eigen::Index> from(static_cast<std::size_t>(n), -1);
  std::vector<bool> in(static_cast<std::size_t>(n), false);
  std::set<Pair> edges;
  double weight = 0.0;
  best[0] = 0.0;
  for (Eigen::Index step = 0; step < n; ++step) {
    Eigen::Index v = -1;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (!in[k] && (v < 0 || best[k] < best[v])) v = k;
    }
    in[v] = true;
    if (from[v] >= 0) {
      weight += best[v];
      edges.insert({std::min<std::uint32_t>(v, from[v]), std::max<std::uint32_t>(v, from[v])});
    }
    for (Eigen::Index k = 0; k < n; ++k) {
      if (!in[k] && distance(f, v, k) < best[k]) {
        best[k] = distance(f, v, k);
        from[k] = v;
      }
    }
  }
  return {edges, weight};
}

std::set<Pair> as_set(const Multipass::Pass& p) { return {p.new_edges.begin(), p.new_edges.end()}; }

// A simple cubic lattice of spacing 1 and radius 0.5: every nearest pair touches.
Frame cubic_lattice(int cells) {
  Frame f = open_frame(cells * cells * cells, cells);
  Eigen::Index k = 0;
  for (int x = 0; x < cells; ++x)
    for (int y = 0; y < cells; ++y)
      for (int z = 0; z < cells; ++z, ++k) f.position().row(k) << x + 0.5, y + 0.5, z + 0.5;
  f.radius().setConstant(0.5);
  return f;
}

// The same particles in another row order (ids travel with them).
Frame shuffled(const Frame& f, unsigned seed) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(f.size()));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  Frame g = open_frame(f.size(), 0.0);
  g.container = f.container;
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    g.position().row(k) = f.position().row(order[k]);
    g.radius()[k] = f.radius()[order[k]];
    g.id()[k] = f.id()[order[k]];
  }
  return g;
}

// The contact pairs each pass first selected, named by particle ids.
std::set<std::tuple<int, std::int64_t, std::int64_t>> selections_by_id(const Frame& f,
                                                                       const TcpReport& r) {
  std::set<std::tuple<int, std::int64_t, std::int64_t>> s;
  for (std::size_t k = 0; k < r.pairs.pairs.size(); ++k) {
    if (r.first_pass[k] == 0) continue;
    const std::int64_t a = f.id()[r.pairs.pairs[k].first], b = f.id()[r.pairs.pairs[k].second];
    s.insert({r.first_pass[k], std::min(a, b), std::max(a, b)});
  }
  return s;
}

MstOptions options(Candidates c, int passes = 5) {
  MstOptions o;
  o.candidates = c;
  o.passes = passes;
  return o;
}

// The paper's Fig. 13: particles 1, 2, 3 (rows 0-2) touch each other, E(1,3) a little
// longer than E(1,2) and E(2,3); 4 and 5 (rows 3, 4) touch; 3 and 4 are the closest pair
// not in contact. The table also holds a wall contact and a pair without force.
Frame figure_13() {
  Frame f = open_frame(5, 20.0);
  f.radius().setConstant(0.5);
  f.position() << 1, 1, 1,  //
      1.96, 1, 1,           // 0.96 from 1
      1.52, 1.83, 1,        // 0.979 from 1, 0.939 from 2
      2.6, 2.4, 1,          // 1.22 from 3
      3.5, 2.6, 1;          // 0.922 from 4
  f.add_contacts(6);
  f.contact_i() << 0, 1, 0, 3, 4, 2;
  f.contact_j() << 1, 2, 2, 4, partner::wall(Wall::ZLow), 3;
  ValueTable<double>& force =
      f.contacts->add<ValueTable<double>>(*find_standard("normal_force", Scope::Contact));
  force.col(2).setConstant(1.0);
  force(5, 2) = 0.0;  // 3-4: in the table, without force
  return f;
}

}  // namespace

TEST(Mst, PassOneIsPrimsTreeForBothCandidateGraphs) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Frame f = random_frame(300, 8.0, seed);
    const auto [edges, weight] = prim(f);
    // cutoff 2.5 (R_i + R_j) >= 2 reaches far enough to keep this graph connected.
    for (const auto& candidates : {cutoff_edges(f, 2.5, "t"), delaunay_edges(f, "t")}) {
      Multipass mst(300, candidates, 1.2);
      const Multipass::Pass p = mst.next();
      ASSERT_EQ(p.edges, 299u) << "seed " << seed;
      EXPECT_NEAR(p.weight, weight, 1e-9 * weight);
      EXPECT_EQ(as_set(p), edges);  // random lengths are distinct
    }
  }
}

TEST(Mst, LatticeTiesGiveOneValidTreeWhateverTheRowOrder) {
  const Frame f = cubic_lattice(5);
  for (Candidates c : {Candidates::Cutoff, Candidates::Delaunay}) {
    FrameCache cache1, cache2;
    const TcpReport a = tcp_report(f, cache1, options(c), "t");
    const Frame g = shuffled(f, 7);
    const TcpReport b = tcp_report(g, cache2, options(c), "t");
    EXPECT_EQ(selections_by_id(f, a), selections_by_id(g, b));
    // Pass 1 selects 124 edges of length 1: Prim's weight.
    EXPECT_EQ(a.passes[0].selected, 124);
    EXPECT_NEAR(prim(f).second, 124.0, 1e-9);
    EXPECT_EQ(a.contacts, 300);  // 3 x 5 x 5 x 4 nearest pairs
  }
}

// The same lattice moved by 0.1, by a whole period, or with its first layer stored at the
// other side of the periodic box: its lengths differ in the last bits, and the passes chose
// other edges (pass 2: 239 contacts, 248 moved by 0.1).
TEST(Mst, LatticeTiesDoNotDependOnWhereTheFrameLies) {
  Frame f = cubic_lattice(5);
  f.container = Container::periodic_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(5));
  FrameCache cache;
  const TcpReport reference = tcp_report(f, cache, options(Candidates::Cutoff), "t");
  for (const double moved : {0.1, 5.0, 1e3}) {
    Frame g = f;
    g.position().array() += moved;
    g.container.lo.array() += moved;
    g.container.hi.array() += moved;
    FrameCache other;
    const TcpReport r = tcp_report(g, other, options(Candidates::Cutoff), "t");
    EXPECT_EQ(selections_by_id(g, r), selections_by_id(f, reference)) << "moved by " << moved;
  }
  Frame image = f;
  for (Eigen::Index k = 0; k < image.size(); ++k)
    if (image.position()(k, 0) < 1.0) image.position()(k, 0) += 5.0;
  FrameCache other;
  const TcpReport r = tcp_report(image, other, options(Candidates::Cutoff), "t");
  EXPECT_EQ(selections_by_id(image, r), selections_by_id(f, reference));
}

// At 1e14 from the origin the tie (64 spacings) is a whole diameter: every length tied, and
// pass 2 selected nothing, exit 0.
TEST(Mst, PositionsRoundedToAFractionOfAContactAreRefused) {
  Frame f = cubic_lattice(3);
  f.position().array() += 1e14;
  f.container = Container::open_top_box(3, Eigen::Vector3d::Constant(1e14),
                                        Eigen::Vector3d::Constant(1e14 + 3.0));
  FrameCache cache;
  EXPECT_EQ(granpipe::test::input_error_of(
                [&] { tcp_report(f, cache, options(Candidates::Cutoff), "frame 0"); }),
            "frame 0: positions up to 1e+14 from the origin are rounded to 0.015625: expected 64 "
            "times that (1) to be at most 0.001 of the smallest contact distance (0.001); move "
            "the origin into the packing");
}

TEST(Mst, PassOneTcpsAreTreesOnTheContactNetworksParticles) {
  // A jittered cubic lattice of touching spheres: contacts by distance, every contact
  // shorter than every other pair, so pass 1 finds each network's particles exactly.
  Frame f = cubic_lattice(6);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.04, 0.04);
  for (Eigen::Index k = 0; k < f.size(); ++k)
    for (int a = 0; a < 3; ++a) f.position()(k, a) += jitter(rng);
  FrameCache cache;
  MstOptions o = options(Candidates::Cutoff, 1);
  o.contacts.tolerance = 0.0;
  const TcpReport r = tcp_report(f, cache, o, "t");
  const Components network = components(static_cast<std::uint32_t>(f.size()), r.pairs.pairs);
  ASSERT_GT(network.counts.others, 0);  // the jitter breaks the network apart
  EXPECT_EQ(r.passes[0].tcp.largest_particles, r.network.largest_particles);
  EXPECT_EQ(r.passes[0].tcp.others, r.network.others);
  EXPECT_TRUE((r.tcp == network.label).all());
  // Every TCP a tree: edges = particles - trees.
  const std::int64_t in_tcps = (r.tcp >= 0).count(), trees = r.tcp.maxCoeff() + 1;
  EXPECT_EQ(r.passes[0].selected, in_tcps - trees);
  EXPECT_EQ(r.unproven, 0);
}

TEST(Mst, Figure13TheSecondPassClosesTheTriangle) {
  const Frame f = figure_13();
  for (Candidates c : {Candidates::Cutoff, Candidates::Delaunay}) {
    FrameCache cache;
    MstOptions o = options(c, 3);
    o.cutoff = 2.0;
    const TcpReport r = tcp_report(f, cache, o, "t");
    EXPECT_TRUE(r.pairs.from_table);
    ASSERT_EQ(r.contacts, 4);  // the zero-force pair does not count
    EXPECT_EQ(r.network.largest_particles, 3);
    EXPECT_EQ(r.network.largest_edges, 3);
    EXPECT_EQ(r.network.others, 1);
    EXPECT_EQ(r.network.other_edges, 1);
    // Pass 1: E(1,2), E(2,3), E(4,5) (and the non-contact E(3,4), deleted).
    EXPECT_EQ(r.passes[0].tcp.largest_particles, 3);
    EXPECT_EQ(r.passes[0].tcp.largest_edges, 2);
    EXPECT_EQ(r.passes[0].tcp.others, 1);
    EXPECT_EQ(r.passes[0].tcp.other_edges, 1);
    EXPECT_EQ(r.recovered(r.passes[0]), 0.75);
    // Pass 2: those lengthened by 1.2, E(1,3) is now the shorter way.
    EXPECT_EQ(r.passes[1].tcp.largest_edges, 3);
    EXPECT_EQ(r.recovered(r.passes[1]), 1.0);
    EXPECT_EQ(r.recovered(r.passes[2]), 1.0);
    const std::vector<int> first_pass = {1, 2, 1, 1};  // pairs 0-1, 0-2, 1-2, 3-4
    EXPECT_EQ(r.first_pass, first_pass);
  }
}

TEST(Mst, TheAutomaticCutoffProvesEveryContactAndAFixedOneSaysWhatItDoesNot) {
  FrameCache cache;
  const TcpReport automatic = tcp_report(figure_13(), cache, options(Candidates::Cutoff, 2), "t");
  // 1.2 x the longest contact (0.979) / (2 x 0.5): E(3,4) = 1.22 is no longer a candidate,
  // and the TCPs are those of Fig. 13 all the same.
  EXPECT_NEAR(automatic.cutoff, 1.2 * 0.979, 1e-3);
  EXPECT_EQ(automatic.unproven, 0);
  EXPECT_EQ(automatic.recovered(automatic.passes[1]), 1.0);

  MstOptions fixed = options(Candidates::Cutoff, 2);
  fixed.cutoff = 1.0;  // every pair below 1.0; the contacts, lengthened, are longer
  EXPECT_EQ(tcp_report(figure_13(), cache, fixed, "t").unproven, 4);
  fixed.passes = 1;  // not lengthened: all shorter than 1.0
  EXPECT_EQ(tcp_report(figure_13(), cache, fixed, "t").unproven, 0);
}

TEST(Mst, ZeroForceContactsCountWhenAsked) {
  FrameCache cache;
  MstOptions o = options(Candidates::Cutoff, 2);
  o.cutoff = 2.0;
  o.contacts.zero_force_contacts = true;
  const TcpReport r = tcp_report(figure_13(), cache, o, "t");
  EXPECT_EQ(r.contacts, 5);
  EXPECT_EQ(r.network.largest_particles, 5);
  EXPECT_EQ(r.passes[0].tcp.largest_edges, 4);  // E(3,4) is now a contact
}

// A ring of 100 edges whose lengths rise by 0.9 of the tie window from E(99,0) down to
// E(0,1), the longest: chained from one length to the next, the whole ring was one tie and
// taken by (i, j), E(0,1) first, so the forest dropped E(98,99) instead of the longest edge:
// 88 windows heavier than minimal. Within one window the ids decide (E(1,2) may go instead).
TEST(Mst, ATieSpansOneWindowNotAChainOfThem) {
  const double tie = 1e-6, step = 0.9 * tie;
  std::vector<Edge> ring;
  for (std::uint32_t k = 0; k < 100; ++k) {
    const std::uint32_t a = k, b = (k + 1) % 100;
    ring.push_back({1.0 + (99 - k) * step, std::min(a, b), std::max(a, b)});
  }
  Multipass mst(100, ring, 1.1, tie);
  const Multipass::Pass first = mst.next();
  double minimal = 0.0;
  for (const Edge& e : ring) minimal += e.weight;
  minimal -= ring[0].weight;  // E(0,1), the longest
  EXPECT_GE(first.weight, minimal - 1e-12);
  EXPECT_LE(first.weight, minimal + tie);
}

TEST(Mst, ASelectedEdgeIsLengthenedOnceNotOncePerPass) {
  // Triangle 0-1-2: E(0,1) = E(1,2) = 1, E(0,2) = 1.1. Lengthened once by 1.05 the two
  // stay shorter than 1.1 in every pass; compounding (1.05^2 > 1.1) would pick E(0,2) in
  // pass 3.
  const std::vector<Edge> triangle = {{1.0, 0, 1}, {1.0, 1, 2}, {1.1, 0, 2}};
  Multipass once(3, triangle, 1.05);
  EXPECT_EQ(once.next().new_edges.size(), 2u);
  EXPECT_NEAR(once.next().weight, 2.1, 1e-12);
  const Multipass::Pass third = once.next();
  EXPECT_TRUE(third.new_edges.empty());
  EXPECT_NEAR(third.weight, 2.1, 1e-12);

  // With 1.2 the second pass takes E(0,2) and, of the equal 1.2s, E(0,1) (lower i, j).
  Multipass longer(3, triangle, 1.2);
  longer.next();
  const Multipass::Pass second = longer.next();
  EXPECT_NEAR(second.weight, 2.3, 1e-12);
  EXPECT_EQ(as_set(second), (std::set<Pair>{{0, 2}}));
}

TEST(Mst, FramesWithoutContactsUseTheCentreDistance) {
  Frame f = figure_13();
  f.contacts.reset();
  FrameCache cache;
  MstOptions o = options(Candidates::Cutoff, 2);
  o.contacts.tolerance = 0.0;
  const TcpReport r = tcp_report(f, cache, o, "t");
  EXPECT_FALSE(r.pairs.from_table);
  EXPECT_EQ(r.contacts, 4);  // 1-2, 1-3, 2-3, 4-5 are closer than 1; 3-4 is not
  EXPECT_EQ(r.recovered(r.passes[1]), 1.0);
}

TEST(Mst, FramesWithoutContactsHaveNoLoadedContacts) {
  Frame f = figure_13();
  FrameCache cache;
  EXPECT_EQ(tcp_report(f, cache, options(Candidates::Cutoff, 2), "t").pairs.loaded, 4);
  f.contacts.reset();
  cache.clear();
  EXPECT_EQ(tcp_report(f, cache, options(Candidates::Cutoff, 2), "t").pairs.loaded, 0);
}

// No contact to recover: the share recovered is 0/0, undefined (NaN), not 0 — and run.log
// says so once; the counts of trees and contacts are 0.
TEST(Mst, WithoutContactsTheRecoveredFractionIsUndefined) {
  const auto ctx = test::make_context("mst", {{"passes", 2}});
  ctx->keep_log();
  MstAnalyzer analyzer(*ctx);
  Frame unloaded = figure_13();
  unloaded.contacts->get<ValueTable<double>>("normal_force").setZero();
  FrameCache cache;
  analyzer.consume(unloaded, cache);
  cache.clear();
  analyzer.consume(unloaded, cache);
  Results r;
  analyzer.finish(r);
  const Table& t = r.tables().at("per_frame");
  ASSERT_EQ(t.rows(), 4u);
  for (std::size_t row = 0; row < t.rows(); ++row) {
    EXPECT_TRUE(std::isnan(t.column("recovered_fraction")[row]));
    EXPECT_EQ(t.column("contacts")[row], 0.0);
    EXPECT_EQ(t.column("tcp_largest_particles")[row], 0.0);
  }
  const std::vector<std::string> lines = ctx->logged_lines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0],
            "warning: mst: frame 0: no contacts: its recovered_fraction is undefined (nan "
            "in per_frame, not 0; docs/mst.md); said for the first such frame only");
}

// Which contact rule applies depends on the data: zero_force_contacts on frames without
// a contact table, or a contact_tolerance on frames with one, did nothing without a word.
TEST(Mst, AContactRuleTheFramesCannotUseIsSaid) {
  const auto said = [](const std::string& param, const nlohmann::json& params, bool table) {
    const auto ctx = test::make_context("mst", params);
    ctx->keep_log();
    MstAnalyzer analyzer(*ctx);
    Frame f = figure_13();
    if (!table) f.contacts.reset();
    FrameCache cache;
    analyzer.consume(f, cache);
    Results r;
    analyzer.finish(r);
    const std::vector<std::string> lines = ctx->logged_lines();
    return std::count_if(lines.begin(), lines.end(), [&](const std::string& l) {
      return l.rfind("warning: mst: " + param + " had no effect", 0) == 0;
    });
  };
  EXPECT_EQ(said("zero_force_contacts", {{"zero_force_contacts", true}}, false), 1);
  EXPECT_EQ(said("zero_force_contacts", {{"zero_force_contacts", true}}, true), 0);
  EXPECT_EQ(said("contact_tolerance", {{"contact_tolerance", 0.5}}, true), 1);
  EXPECT_EQ(said("contact_tolerance", {{"contact_tolerance", 0.5}}, false), 0);
  EXPECT_EQ(said("contact_tolerance", {}, true), 0);
}

TEST(Mst, ANaNForceOrARowJoiningAParticleToItselfIsRefused) {
  FrameCache cache;
  Frame nan_force = figure_13();
  nan_force.contacts->get<ValueTable<double>>("normal_force")(1, 0) = std::nan("");
  MstOptions o = options(Candidates::Cutoff, 2);
  o.contacts.zero_force_contacts = true;  // refused whether the forces count or not
  EXPECT_EQ(granpipe::test::input_error_of([&] { tcp_report(nan_force, cache, o, "frame 3"); }),
            "frame 3: contact 1: expected a finite normal_force, got nan in component x");
  Frame self = figure_13();
  self.contact_j()[0] = 0;
  EXPECT_EQ(granpipe::test::input_error_of(
                [&] { tcp_report(self, cache, options(Candidates::Cutoff, 2), "frame 3"); }),
            "frame 3: contact 0: expected two different particles, got particle 0 twice");
}

TEST(Mst, DelaunayKeepsParticlesAtOnePosition) {
  Frame f = random_frame(20, 4.0, 9);
  f.position().row(7) = f.position().row(3);
  f.position().row(12) = f.position().row(3);
  Multipass mst(20, delaunay_edges(f, "t"), 1.2);
  EXPECT_EQ(mst.next().edges, 19u);
}

TEST(Mst, DelaunayRefusesPeriodicSides) {
  Frame f = random_frame(10, 4.0, 1);
  f.container = Container::periodic_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(4.0));
  EXPECT_EQ(granpipe::test::input_error_of([&] { delaunay_edges(f, "frame 2"); }),
            "frame 2: candidates \"delaunay\" expected a container without periodic sides, "
            "got a periodic axis 0 (use candidates \"cutoff\")");
}

TEST(Mst, CutoffCandidatesCrossPeriodicSides) {
  Frame f = open_frame(2, 4.0);
  f.container = Container::periodic_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(4.0));
  f.radius().setConstant(0.5);
  f.position() << 0.2, 2, 2, 3.7, 2, 2;
  const std::vector<Edge> e = cutoff_edges(f, 1.25, "t");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_NEAR(e[0].weight, 0.5, 1e-12);
}

// A cutoff far too large made every pair of a large frame a candidate: std::bad_alloc,
// exit 1, for a frame of some 10^4 particles. Refused past 500 candidates per particle.
TEST(Mst, ACutoffThatMakesTheCandidateGraphNearlyCompleteIsRefused) {
  const Frame f = cubic_lattice(11);  // 1331 particles: 885115 pairs
  EXPECT_EQ(granpipe::test::input_error_of([&] { cutoff_edges(f, 1e6, "frame 0"); }),
            "frame 0: cutoff: expected at most 500 candidate pairs per particle (665500 for "
            "1331 particles), got more with cutoff 1e+06 (the automatic cutoff, 0, stops at "
            "3)");
  EXPECT_FALSE(cutoff_edges(f, 3.0, "frame 0").empty());  // the largest automatic one
}

TEST(Mst, TheAnalyzerPublishesPassesAndTreesAndKeepsTheMostLoadedFrame) {
  const auto ctx = test::make_context("mst", {{"cutoff", 2.0}, {"passes", 2}});
  MstAnalyzer analyzer(*ctx);
  FrameCache cache;
  Frame fewer = figure_13();
  fewer.contacts->get<ValueTable<double>>("normal_force")(2, 2) = 0.0;  // 1-3 unloaded
  fewer.time = 1.0;
  analyzer.consume(fewer, cache);
  cache.clear();
  Frame f = figure_13();
  f.time = 2.0;
  analyzer.consume(f, cache);

  PropertyTable contacts(Scope::Contact, f.contacts->rows(), 3), particles(Scope::Particle, 5, 3);
  for (const Property& p : analyzer.publishes())
    (p.scope == Scope::Contact ? contacts : particles).add(p);
  analyzer.publish(contacts);
  analyzer.publish(particles);
  const IndexArray& pass = contacts.get<IndexArray>("mst_pass");
  EXPECT_EQ(pass[0], 1);  // 1-2
  EXPECT_EQ(pass[1], 1);  // 2-3
  EXPECT_EQ(pass[2], 2);  // 1-3
  EXPECT_EQ(pass[3], 1);  // 4-5
  EXPECT_EQ(pass[4], 0);  // a wall
  EXPECT_EQ(pass[5], 0);  // no force
  const IndexArray& tcp = particles.get<IndexArray>("tcp");
  EXPECT_TRUE((tcp == (IndexArray(5) << 0, 0, 0, 1, 1).finished()).all());

  Results r;
  analyzer.finish(r);
  EXPECT_EQ(r.tables().at("per_frame").rows(), 4u);
  EXPECT_EQ(r.tables().at("table_ii").rows(), 2u);
  EXPECT_EQ(r.scalar("table_ii_time").value, 2.0);
  EXPECT_EQ(r.tables().at("table_ii").column("recovered_fraction")[1], 1.0);
}
