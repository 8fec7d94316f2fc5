// force_network on hand-made contact tables whose answers are counted by hand, the Eq. (11)
// fit on samples drawn from Eq. (11), and F(r) against a direct O(M^2) sum.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "force_correlation.hpp"
#include "force_network_analyzer.hpp"
#include "pass_subsets.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
using namespace granpipe::force_network;

namespace {

struct ContactSpec {
  std::int64_t i, j;
  double force;       // |F_n|, along x
  std::int64_t pass;  // the hand-made mst_pass
};

const std::int64_t kBase = partner::wall(Wall::ZLow);

// Particles 0..3: a triangle with a tail; 5-6-7 a chain whose 7-8 contact carries no
// force; pairs 9-10 and 11-12 (listed first, so that the label order is not the table's);
// 4 touches only the base. Edge forces sum to 20 over 8 edges: <F_n> = 2.5.
const std::vector<ContactSpec> kTable = {
    {11, 12, 4, 3}, {5, 6, 1, 1}, {2, 3, 6, 1}, {7, 8, 0, 1}, {0, 1, 1, 1},    {4, kBase, 10, 0},
    {9, 10, 2, 1},  {1, 2, 2, 1}, {6, 7, 1, 2}, {2, 0, 3, 2}, {0, kBase, 5, 0}};

Property pass_property() { return {"mst_pass", Scope::Contact, ValueType::Integer, 1, "", "pass"}; }

// `n` particles along x (x = 2 i, radius 1) and the contacts of `table`, each with its
// force along x, its contact point (the midpoint, or the particle for a wall) and its pass.
Frame frame_of(const std::vector<ContactSpec>& table, Eigen::Index n = 13) {
  Frame f;
  f.resize(n, 3);
  for (Eigen::Index p = 0; p < n; ++p) f.position()(p, 0) = 2.0 * static_cast<double>(p);
  f.radius().setConstant(1.0);
  f.container = Container::open_top_box(3, Eigen::Vector3d(-2, -2, -2),
                                        Eigen::Vector3d(2.0 * static_cast<double>(n), 2, 2));
  const auto m = static_cast<Eigen::Index>(table.size());
  PropertyTable& c = f.add_contacts(m);
  auto& force = c.add<Coordinates>(*find_standard("normal_force", Scope::Contact));
  auto& point = c.add<Coordinates>(*find_standard("point", Scope::Contact));
  auto& pass = c.add<IndexArray>(pass_property());
  for (Eigen::Index k = 0; k < m; ++k) {
    const ContactSpec& s = table[static_cast<std::size_t>(k)];
    f.contact_i()[k] = s.i;
    f.contact_j()[k] = s.j;
    force(k, 0) = s.force;
    const Eigen::Index other = s.j >= 0 ? s.j : s.i;
    point.row(k) = 0.5 * (f.position().row(s.i) + f.position().row(other));
    pass[k] = s.pass;
  }
  return f;
}

struct Outcome {
  Results results;
  IndexArray network;
  IntArray strong;
};

// The analyzer with `params` on one frame: its results and published columns.
Outcome run(const Frame& frame, const nlohmann::json& params = nlohmann::json::object()) {
  const auto ctx = test::make_context("force_network", params);
  ForceNetworkAnalyzer analyzer(*ctx);
  FrameCache cache;
  analyzer.consume(frame, cache);
  PropertyTable particles(Scope::Particle, frame.size(), 3),
      contacts(Scope::Contact, frame.contacts->rows(), 3);
  particles.add(ForceNetworkAnalyzer::network_property());
  contacts.add(ForceNetworkAnalyzer::strong_property());
  analyzer.publish(particles);
  analyzer.publish(contacts);
  Outcome r;
  analyzer.finish(r.results);
  r.network = particles.get<IndexArray>("network");
  r.strong = contacts.get<IntArray>("strong");
  return r;
}

double per_frame(const Outcome& r, const std::string& column) {
  return r.results.tables().at("per_frame").column(column).at(0);
}

std::string refusal(const Frame& frame, const nlohmann::json& params = nlohmann::json::object()) {
  try {
    run(frame, params);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(ForceNetwork, NetworksAreComponentsOfLoadedPairContactsLabelledBySize) {
  const Outcome r = run(frame_of(kTable));
  IndexArray expected(13);
  expected << 0, 0, 0, 0, -1, 1, 1, 1, -1, 2, 2, 3, 3;
  EXPECT_TRUE((r.network == expected).all()) << r.network.transpose();
  EXPECT_EQ(per_frame(r, "networks"), 4);
  EXPECT_EQ(per_frame(r, "largest_particles"), 4);
  EXPECT_EQ(per_frame(r, "largest_contacts"), 4);
  EXPECT_EQ(per_frame(r, "other_networks"), 3);
  EXPECT_EQ(per_frame(r, "other_contacts"), 4);  // 2 + 1 + 1
  EXPECT_EQ(per_frame(r, "z_largest"), 2.0);
  EXPECT_DOUBLE_EQ(per_frame(r, "z_mean"), 16.0 / 13.0);
  EXPECT_EQ(per_frame(r, "network_contacts"), 8);
  EXPECT_EQ(per_frame(r, "loaded_pair_contacts"), 8);
  EXPECT_EQ(per_frame(r, "mean_force"), 2.5);
}

TEST(ForceNetwork, MinForceRemovesWeakerContactsFromTheNetworks) {
  const Outcome r = run(frame_of(kTable), {{"min_force", 1.5}});
  EXPECT_EQ(per_frame(r, "networks"), 3);  // the 5-6-7 chain carries only F = 1
  EXPECT_EQ(per_frame(r, "largest_contacts"), 3);
  EXPECT_EQ(per_frame(r, "mean_force"), 17.0 / 5.0);
  EXPECT_EQ(per_frame(r, "loaded_pair_contacts"), 8);  // the frame choice ignores min_force
}

TEST(ForceNetwork, StrongSubNetworkIsTheContactsAboveTheMean) {
  const Outcome r = run(frame_of(kTable));
  IntArray expected = IntArray::Zero(11);
  expected[0] = expected[2] = expected[9] = 1;  // F = 4, 6, 3 > 2.5
  EXPECT_TRUE((r.strong == expected).all()) << r.strong.transpose();
  EXPECT_EQ(per_frame(r, "strong_contacts"), 3);
  EXPECT_EQ(per_frame(r, "strong_particles"), 5);             // 0, 2, 3, 11, 12
  EXPECT_EQ(per_frame(r, "strong_particles_in_largest"), 3);  // 0, 2, 3
  EXPECT_EQ(per_frame(r, "strong_largest_particles"), 3);
  EXPECT_EQ(per_frame(r, "strong_largest_contacts"), 2);
}

// Equal forces are no stronger than their mean: with a plain sum, 300 contacts of 0.3 had
// the mean 0.2999999999999983 and were all strong; 0.1, 0.3 and 0.5 a hundred times each
// had 200 strong contacts, not the hundred of 0.5.
TEST(ForceNetwork, ContactsAtTheMeanForceAreNotStrong) {
  std::vector<ContactSpec> equal, three;
  for (std::int64_t k = 0; k < 300; ++k) {
    equal.push_back({k, k + 1, 0.3, 1});
    three.push_back({k, k + 1, k % 3 == 0 ? 0.1 : k % 3 == 1 ? 0.3 : 0.5, 1});
  }
  const Outcome same = run(frame_of(equal, 301));
  EXPECT_EQ(per_frame(same, "mean_force"), 0.3);
  EXPECT_EQ(per_frame(same, "strong_contacts"), 0);
  const Outcome mixed = run(frame_of(three, 301));
  EXPECT_EQ(per_frame(mixed, "mean_force"), 0.3);
  EXPECT_EQ(per_frame(mixed, "strong_contacts"), 100);
}

TEST(ForceNetwork, WallContactsJoinTheStatisticsOnlyWhenAsked) {
  const Outcome r = run(frame_of(kTable), {{"walls", true}});
  EXPECT_EQ(per_frame(r, "samples"), 10);
  EXPECT_EQ(per_frame(r, "mean_force"), 3.5);     // (20 + 10 + 5) / 10
  EXPECT_EQ(per_frame(r, "strong_contacts"), 2);  // 6 and 4
  EXPECT_EQ(per_frame(r, "networks"), 4);         // walls never link particles
}

// Wall contacts only, counted: samples and a mean force, but no network, and z_largest was
// NaN without a word.
TEST(ForceNetwork, WallContactsAloneLeaveZLargestUndefinedAndSaid) {
  const auto ctx = test::make_context("force_network", {{"walls", true}});
  ctx->keep_log();
  ForceNetworkAnalyzer analyzer(*ctx);
  FrameCache cache;
  analyzer.consume(frame_of({{4, kBase, 10, 0}, {0, kBase, 5, 0}}), cache);
  Results results;
  analyzer.finish(results);
  EXPECT_EQ(results.tables().at("per_frame").column("mean_force")[0], 7.5);
  EXPECT_TRUE(std::isnan(results.tables().at("per_frame").column("z_largest")[0]));
  EXPECT_EQ(ctx->logged_lines(),
            (std::vector<std::string>{
                "warning: force_network: frame 0: no pair contact with |F_n| > min_force (wall "
                "contacts only): no network, and z_largest is undefined (nan in the results, "
                "not 0; docs/force_network.md); said for the first such frame only"}));
}

TEST(ForceNetwork, PdfIsANormalisedDensity) {
  const Outcome r = run(frame_of(kTable));
  const Table& pdf = r.results.tables().at("pdf");
  double integral = 0.0, count = 0.0;
  for (std::size_t k = 0; k < pdf.rows(); ++k) {
    integral += pdf.column("density")[k] * (pdf.column("f_hi")[k] - pdf.column("f_lo")[k]);
    count += pdf.column("count")[k];
  }
  EXPECT_NEAR(integral, 1.0, 1e-12);
  EXPECT_EQ(count, 8);
  EXPECT_NEAR(pdf.column("f_hi").back(), 2.4, 1e-12);  // largest f = 6 / 2.5, whole bins of 0.2
}

// f = |F_n|/<F_n> does not depend on the unit of force. Forces of 1e160 along x and y
// squared past the largest double: every f NaN and a message of a NaN bin_width. (Bins of
// 0.25: no f = 0.4 k lies on an edge, where the last bit of the two units' means decides.)
TEST(ForceNetwork, ThePdfDoesNotDependOnTheUnitOfForce) {
  Frame unit = frame_of(kTable), huge = frame_of(kTable);
  auto& force = huge.contacts->get<Coordinates>("normal_force");
  unit.contacts->get<Coordinates>("normal_force").col(1) =
      unit.contacts->get<Coordinates>("normal_force").col(0);
  force.col(0) *= 1e160;
  force.col(1) = force.col(0);
  const Outcome small = run(unit, {{"bin_width", 0.25}});
  const Table& a = small.results.tables().at("pdf");
  const Outcome big = run(huge, {{"bin_width", 0.25}});
  const Table& b = big.results.tables().at("pdf");
  ASSERT_EQ(a.rows(), b.rows());
  for (std::size_t k = 0; k < a.rows(); ++k) {
    EXPECT_EQ(a.column("count")[k], b.column("count")[k]);
    EXPECT_NEAR(a.column("density")[k], b.column("density")[k], 1e-12);
  }
  EXPECT_NEAR(per_frame(big, "mean_force") / 1e160, 2.5 * std::sqrt(2.0), 1e-12);
  force.row(5).setConstant(1.7e308);  // the wall row: its magnitude is past the largest double
  EXPECT_EQ(refusal(huge),
            "frame 0: contact 5: expected normal forces whose mean is a finite number, got "
            "|F_n| = inf");
}

// Too few samples: the fit is undefined (NaN, not 0), every measured statistic finite but
// F(r) where no pair falls (NaN too).
TEST(ForceNetwork, TooFewSamplesAreNotFittedAndOnlyTheFitIsNaN) {
  const Outcome r = run(frame_of(kTable));
  EXPECT_EQ(r.results.scalar("eq11_status").value, 1.0);  // too few samples
  EXPECT_TRUE(r.results.fits().empty());
  const std::set<std::string> fit = {"a",        "a_err",        "b",   "b_err", "beta",
                                     "beta_err", "chi2_per_dof", "eq11"};
  for (const auto& [name, t] : r.results.tables()) {
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      for (std::size_t k = 0; k < t.data[c].size(); ++k) {
        const bool empty_bin =
            name == "correlation" && t.columns[c] == "F" && t.column("pairs")[k] == 0.0;
        EXPECT_EQ(std::isnan(t.data[c][k]), fit.contains(t.columns[c]) || empty_bin) << name;
      }
    }
  }
  for (const auto& [name, s] : r.results.scalars()) EXPECT_TRUE(std::isfinite(s.value)) << name;
}

// No loaded contact (every force zero, or an empty contact table): <F_n> is 0/0 and there
// is no network, so the mean force, the largest network's z and the PDF are undefined:
// NaN, with one warning in run.log for the run, and so is the Eq. (11) fit that could not
// be made (its parameters, errors, chi^2 per dof and curve). Counts stay counts: 0.
TEST(ForceNetwork, WithoutLoadedContactsTheStatisticsAreUndefinedNotZero) {
  std::vector<ContactSpec> unloaded = kTable;
  for (ContactSpec& s : unloaded) s.force = 0.0;
  const std::set<std::string> undefined = {
      "mean_force", "z_largest", "density",  "error",        "a",   "a_err", "b",
      "b_err",      "beta",      "beta_err", "chi2_per_dof", "eq11"};
  for (const auto& table : {unloaded, std::vector<ContactSpec>{}}) {
    const auto ctx = test::make_context("force_network");
    ctx->keep_log();
    ForceNetworkAnalyzer analyzer(*ctx);
    FrameCache cache;
    for (int frame = 0; frame < 2; ++frame) analyzer.consume(frame_of(table), cache);
    Results results;
    analyzer.finish(results);
    EXPECT_EQ(results.scalar("eq11_status").value, 1.0);
    for (const std::string name : {"per_frame", "pdf"}) {
      const Table& t = results.tables().at(name);
      for (std::size_t c = 0; c < t.columns.size(); ++c) {
        for (double x : t.data[c]) {
          EXPECT_EQ(std::isnan(x), undefined.contains(t.columns[c])) << name << "." << t.columns[c];
        }
      }
    }
    EXPECT_EQ(results.tables().at("per_frame").column("networks").at(0), 0.0);
    const std::vector<std::string> lines = ctx->logged_lines();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0],
              "warning: force_network: frame 0: no contact with |F_n| > min_force: its "
              "mean_force, z_largest and force PDF are undefined (nan in the results, "
              "not 0; docs/force_network.md); said for the first such frame only");
  }
}

// Bins of f_max / round(f_max / bin_width) were 0.1667 wide for 0.2 asked.
TEST(ForceNetwork, PdfBinsAreBinWidthWideUpToFMaxRoundedUp) {
  const std::vector<double> f{0.1, 0.3};
  EXPECT_EQ(pdf_edges(f, 0.5, 0.25), (std::vector<double>{0.0, 0.25, 0.5}));
  const std::vector<double> edges = pdf_edges(f, 0.5, 0.2);
  ASSERT_EQ(edges.size(), 4u);
  for (std::size_t k = 0; k < edges.size(); ++k) EXPECT_DOUBLE_EQ(edges[k], 0.2 * k);
  // A bin wider than f_max would be one past it.
  EXPECT_EQ(refusal(frame_of(kTable), {{"f_max", 0.1}, {"bin_width", 1.0}}),
            "params.bin_width: expected at most f_max (0.1), got 1: a single bin would reach "
            "past it");
}

// All forces equal: f = 1 for every contact, a PDF that is one spike (five bins of 0.2, the
// last one full), which Eq. (11) cannot follow: the minimiser fails, and that is a status,
// with finite (zero) values.
// Not fitted is undefined: NaN values and errors, never a 0 that reads as a result.
TEST(ForceNetwork, ASpikeOfEqualForcesIsNotFittedAndReportedUndefined) {
  std::vector<double> f(500, 1.0);
  const PdfFit fit = fit_pdf(force_pdf(f, pdf_edges(f, 0.0, 0.2)), eq11_request(100));
  EXPECT_EQ(fit.status, FitStatus::NotConverged);
  for (int q = 0; q < kParameters; ++q) {
    EXPECT_TRUE(std::isnan(fit.value[q]) && std::isnan(fit.error[q])) << kParameterNames[q];
  }
  EXPECT_TRUE(std::isfinite(fit.chi2));
}

TEST(ForceNetwork, AFrameWithoutContactsIsRefused) {
  Frame f = frame_of(kTable);
  f.contacts.reset();
  EXPECT_EQ(refusal(f),
            "frame 0: expected a contact table with normal_force, got a frame "
            "without contacts");
}

TEST(ForceNetwork, ANonFiniteContactPointIsRefused) {
  Frame f = frame_of(kTable);
  f.contacts->get<Coordinates>("point")(4, 1) = std::nan("");
  EXPECT_EQ(refusal(f),
            "frame 0: contact 4: expected a finite contact point, got a NaN or "
            "infinite coordinate");
}

TEST(ForceNetwork, ANaNForceOrARowJoiningAParticleToItselfIsRefused) {
  Frame nan_force = frame_of(kTable);
  nan_force.contacts->get<Coordinates>("normal_force")(5, 0) = std::nan("");  // a wall row
  EXPECT_EQ(refusal(nan_force),
            "frame 0: contact 5: expected a finite normal_force, got nan in "
            "component x");
  Frame self = frame_of(kTable);
  self.contact_j()[2] = 2;
  EXPECT_EQ(refusal(self),
            "frame 0: contact 2: expected two different particles, got particle 2 "
            "twice");
}

TEST(ForceNetwork, RMaxBeyondHalfAPeriodicBoxIsRefused) {
  Frame f = frame_of(kTable);
  f.container = Container::periodic_box(3, Eigen::Vector3d(-2, -2, -2), Eigen::Vector3d(26, 2, 2));
  const std::string m = refusal(f, {{"r_max", 3}});
  EXPECT_EQ(m.rfind("frame 0: F(r) up to r_max (parameter r_max): neighbour search: expected a "
                    "periodic box of length at least 6",
                    0),
            0u)
      << m;
}

TEST(ForceNetwork, BadParametersAreRefusedWithTheirPath) {
  EXPECT_EQ(refusal(frame_of(kTable), {{"by_pass", "2nd pass"}}),
            "params.by_pass: expected a contact column name (letters, digits and '_', not "
            "starting with a digit) or \"\", got \"2nd pass\"");
  EXPECT_EQ(refusal(frame_of(kTable), {{"f_max", 1e9}}),
            "params.f_max: expected at most 10000 bins of bin_width, got f_max / bin_width = "
            "5e+09");
  EXPECT_THROW(test::make_context("force_network", {{"bin_width", 0}}), InputError);
  // f_max 0 with a bin too narrow for the frame's largest f, 2.4: the PDF stopped at its
  // most bins and left the larger forces out of it and its fit, exit 0.
  EXPECT_EQ(refusal(frame_of(kTable), {{"bin_width", 1e-5}}),
            "frame 0: bin_width (f_max 0: the PDF reaches the frame's largest f): expected at "
            "most 10000 bins, got 240000 (2.4 in steps of 1e-05)");
  EXPECT_EQ(refusal(frame_of(kTable), {{"bin_width", 2.4e-4}}), "no error");  // 10000 bins
}

// Samples of Eq. (11) by rejection: f from exp(-beta f), kept with probability
// 1 - b exp(-f^2) (which is at most 1).
std::vector<double> eq11_samples(double b, double beta, std::size_t count) {
  std::mt19937_64 rng(20261123);
  std::exponential_distribution<double> tail(beta);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> f;
  while (f.size() < count) {
    const double x = tail(rng);
    if (u(rng) < 1.0 - b * std::exp(-x * x)) f.push_back(x);
  }
  return f;
}

// The a that normalises Eq. (11) over f > 0.
double normalising_a(double b, double beta) {
  const double bump =
      0.5 * std::sqrt(std::numbers::pi) * std::exp(0.25 * beta * beta) * std::erfc(0.5 * beta);
  return 1.0 / (1.0 / beta - b * bump);
}

TEST(ForceNetwork, Eq11FitRecoversTheParametersOfItsOwnSamples) {
  const double b = 0.83, beta = 1.35, a = normalising_a(b, beta);
  const std::vector<double> f = eq11_samples(b, beta, 100000);
  const PdfFit fit = fit_pdf(force_pdf(f, pdf_edges(f, 0.0, 0.1)), eq11_request(100));
  ASSERT_TRUE(fit.fitted()) << describe(fit.status);
  for (auto [q, truth] : {std::pair{kA, a}, {kB, b}, {kBeta, beta}}) {
    EXPECT_LT(std::abs(fit.value[q] - truth), 3.0 * fit.error[q]) << kParameterNames[q];
    EXPECT_LT(std::abs(fit.value[q] / truth - 1.0), 0.03) << kParameterNames[q];
    EXPECT_GT(fit.error[q], 0.0);
  }
  EXPECT_EQ(fit.value[kAlpha], 0.0);
  EXPECT_EQ(fit.value[kGamma], 0.0);
}

// The shift fit of an exactly exponential PDF against a reference with a plateau
// (b = 0.83): the best fit moves the bump out of the bins, where alpha no longer changes
// anything. It is reported as not determined, without values, not fitted with an error of
// 1e8 or more.
TEST(ForceNetwork, AParameterTheDataDoNotDetermineIsNotReportedAsFitted) {
  const double beta = 1.35;
  ForcePdf pdf{.edges = {}, .counts = {}, .samples = 100000};
  for (int k = 0; k <= 60; ++k) pdf.edges.push_back(0.1 * k);
  for (int k = 0; k < 60; ++k) {
    pdf.counts.push_back(100000.0 *
                         (std::exp(-beta * pdf.edges[k]) - std::exp(-beta * pdf.edges[k + 1])));
  }
  FitRequest shift;
  shift.start = {normalising_a(0.83, beta), 0.83, 0.0, beta, 0.0};
  shift.free = {false, false, true, false, true};
  const PdfFit fit = fit_pdf(pdf, shift);
  EXPECT_EQ(fit.status, FitStatus::NotDetermined)
      << fit.value[kAlpha] << " +- " << fit.error[kAlpha];
  EXPECT_STREQ(describe(fit.status), "not fitted: a parameter is not determined by the data");
  EXPECT_TRUE(std::isnan(fit.value[kAlpha]));
  EXPECT_TRUE(std::isnan(fit.error[kAlpha]));

  // A peak (b < 0) the data hold no trace of: the fit keeps it inside the bins, where
  // alpha is determined.
  shift.start[kB] = -0.5;
  const PdfFit peak = fit_pdf(pdf, shift);
  ASSERT_EQ(peak.status, FitStatus::Fitted);
  EXPECT_GT(peak.value[kAlpha], 0.0);
  EXPECT_LT(peak.error[kAlpha], 0.1);
}

// Eq. (12) summed over every ordered pair i != j, binned as force_correlation bins.
ForceCorrelation direct_correlation(const Coordinates& x, const std::vector<double>& f,
                                    const Container& c, double r_max, int bins) {
  ForceCorrelation out{r_max, std::vector<double>(static_cast<std::size_t>(bins), 0.0),
                       std::vector<double>(static_cast<std::size_t>(bins), 0.0)};
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (Eigen::Index j = 0; j < x.rows(); ++j) {
      if (i == j) continue;
      double r2 = 0.0;
      for (int a = 0; a < 3; ++a) {
        const double d = c.minimum_image(a, x(j, a) - x(i, a));
        r2 += d * d;
      }
      const auto k = static_cast<std::size_t>(std::sqrt(r2) / (r_max / bins));
      if (k >= out.bins() || r2 > r_max * r_max) continue;
      out.product_sum[k] += f[static_cast<std::size_t>(i)] * f[static_cast<std::size_t>(j)];
      out.pairs[k] += 1.0;
    }
  }
  return out;
}

// Contact points on a simple cubic lattice of spacing 1, side `n`, with forces 1 + k % 7 / 10.
void expect_lattice_correlation_is_direct(const Container& c, int n, double r_max) {
  Coordinates x(n * n * n, 3);
  std::vector<double> f;
  for (int k = 0; k < n * n * n; ++k) {
    x.row(k) << 0.5 + k % n, 0.5 + (k / n) % n, 0.5 + k / (n * n);
    f.push_back(1.0 + (k % 7) / 10.0);
  }
  const int bins = 35;
  const ForceCorrelation fast = force_correlation(x, f, c, 3, r_max, bins, "test");
  const ForceCorrelation slow = direct_correlation(x, f, c, r_max, bins);
  double pairs = 0.0;
  for (std::size_t k = 0; k < fast.bins(); ++k) {
    EXPECT_EQ(2.0 * fast.pairs[k], slow.pairs[k]) << k;  // the direct sum counts both orders
    if (fast.pairs[k] == 0.0) {
      EXPECT_TRUE(std::isnan(fast.value(k))) << k;  // no pair: undefined, not 0
      continue;
    }
    EXPECT_NEAR(fast.value(k), slow.value(k), 1e-13 * std::abs(slow.value(k))) << k;
    pairs += fast.pairs[k];
  }
  EXPECT_GT(pairs, 0.0);
}

TEST(ForceNetwork, CorrelationOfALatticeEqualsTheDirectSum) {
  expect_lattice_correlation_is_direct(
      Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(6)), 6, 3.5);
  expect_lattice_correlation_is_direct(
      Container::periodic_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(8)), 8, 3.5);
}

TEST(ForceNetwork, ByPassReportsTheContactsOfPassesOneToK) {
  const Outcome r = run(frame_of(kTable), {{"by_pass", "mst_pass"}});
  const Table& fits = r.results.tables().at("pass_fits");
  ASSERT_EQ(fits.rows(), 3u);
  EXPECT_EQ(fits.column("contacts"), (std::vector<double>{5, 7, 8}));      // 7-8 carries no force
  EXPECT_EQ(fits.column("free_status"), (std::vector<double>{1, 1, 1}));   // too few samples
  EXPECT_EQ(fits.column("shift_status"), (std::vector<double>{3, 3, 3}));  // no Eq. (11) fit
  const Table& pdf = r.results.tables().at("pass_pdf");
  EXPECT_EQ(pdf.column("density_pass_3"), pdf.column("density_all"));
  double integral = 0.0;
  for (double d : pdf.column("density_pass_1")) integral += 0.2 * d;  // bins of 0.2
  EXPECT_NEAR(integral, 1.0, 1e-12);  // each subset's PDF is a density of its own
  // Scaled by the full network's mean (2.5), pass 1's largest force 6 is at f = 2.4, the top
  // of the full network's last bin [2.2, 2.4]: one of its five contacts.
  EXPECT_NEAR(pdf.column("density_pass_1").back(), 1.0 / (5 * 0.2), 1e-9);
  const Table& correlation = r.results.tables().at("pass_correlation");
  const auto& all = correlation.column("F_all");
  const auto& pass_3 = correlation.column("F_pass_3");
  for (std::size_t k = 0; k < all.size(); ++k) {
    // Bins without a pair are undefined in both.
    if (std::isnan(all[k])) {
      EXPECT_TRUE(std::isnan(pass_3[k])) << k;
    } else {
      EXPECT_EQ(pass_3[k], all[k]) << k;
    }
  }
}

TEST(ForceNetwork, ByPassIsNeededOnlyWhenSetAndNamedWhenMissing) {
  const auto off = test::make_context("force_network");
  EXPECT_EQ(ForceNetworkAnalyzer(*off).needs().columns.size(), 2u);
  const auto on = test::make_context("force_network", {{"by_pass", "mst_pass"}});
  const FrameContent needs = ForceNetworkAnalyzer(*on).needs();
  ASSERT_EQ(needs.columns.size(), 3u);
  EXPECT_TRUE(needs.columns.back().matches(pass_property()));

  Frame f = frame_of(kTable);
  f.contacts->remove("mst_pass");
  EXPECT_EQ(refusal(f, {{"by_pass", "mst_pass"}}),
            "frame 0: expected the contact column mst_pass (parameter by_pass), got contacts "
            "without it");
}

// A negative pass number counted as none, and a column of no pass (every row 0) left the
// pass tables out without a word, exit 0.
TEST(ForceNetwork, ByPassRefusesNegativePassesAndSaysWhenThereIsNone) {
  Frame f = frame_of(kTable);
  auto& pass = f.contacts->get<IndexArray>("mst_pass");
  pass[2] = -5;
  EXPECT_EQ(refusal(f, {{"by_pass", "mst_pass"}}),
            "frame 0: contact 2: contact column mst_pass (by_pass): expected a pass number, 0 "
            "(none) or more, got -5");
  pass.setZero();
  const auto ctx = test::make_context("force_network", {{"by_pass", "mst_pass"}});
  ctx->keep_log();
  ForceNetworkAnalyzer analyzer(*ctx);
  FrameCache cache;
  analyzer.consume(f, cache);
  Results results;
  analyzer.finish(results);
  EXPECT_EQ(results.tables().count("pass_fits"), 0u);
  EXPECT_EQ(ctx->logged_lines(),
            (std::vector<std::string>{"warning: force_network: by_pass: contact column mst_pass "
                                      "of frame 0 (the one analysed in full) names no pass "
                                      "(every row 0): no pass_* results"}));
}

// Many contacts drawn from Eq. (11), each captured by pass 1 or 2 at random: each subset
// has the full network's distribution, so the shift fit finds alpha, gamma ~ 0 and the
// free fit alpha ~ 0 and the distribution's beta. The forces are scaled by their mean, so
// they are drawn with the beta for which Eq. (11) at b = 0.83 has mean 1 (solved with
// scipy's brentq from the closed form of the mean).
TEST(ForceNetwork, ByPassFitsOfASubsetOfTheSameDistribution) {
  const double beta = 1.5879873;
  const std::vector<double> forces = eq11_samples(0.83, beta, 40000);
  std::vector<ContactSpec> table;
  std::mt19937_64 rng(7);
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const auto i = static_cast<std::int64_t>(2 * k);
    table.push_back({i, i + 1, forces[k], static_cast<std::int64_t>(1 + rng() % 2)});
  }
  const Frame frame = frame_of(table, static_cast<Eigen::Index>(2 * forces.size()));
  const Outcome r = run(frame, {{"by_pass", "mst_pass"}, {"bin_width", 0.1}, {"r_max", 2.5}});
  ASSERT_EQ(r.results.scalar("eq11_status").value, 0.0);
  const Table& fits = r.results.tables().at("pass_fits");
  ASSERT_EQ(fits.rows(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_EQ(fits.column("free_status")[k], 0.0);
    ASSERT_EQ(fits.column("shift_status")[k], 0.0);
    for (const char* shift : {"shift_alpha", "shift_gamma"}) {
      EXPECT_LT(std::abs(fits.column(shift)[k]), 3.0 * fits.column(std::string(shift) + "_err")[k]);
    }
    EXPECT_LT(std::abs(fits.column("free_alpha")[k]), 3.0 * fits.column("free_alpha_err")[k]);
    EXPECT_NEAR(fits.column("free_beta")[k], beta, 3.0 * fits.column("free_beta_err")[k]);
  }
  EXPECT_TRUE(r.results.fits().count("pass_1_eq13_shift"));
}
