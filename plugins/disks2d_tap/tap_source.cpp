#include "tap_source.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <sstream>
#include <utility>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/start_frame.hpp"
#include "granpipe/step_count.hpp"
#include "placement.hpp"

namespace granpipe::disks2d_tap {

namespace {
// How the amplitude goes: one value, or ramped up and down (parameter protocol).
enum class Protocol : std::uint8_t { Constant, Annealed };
ChoiceNames<Protocol> choice_names(Protocol) {
  return {{"constant", Protocol::Constant}, {"annealed", Protocol::Annealed}};
}
// A start from a file takes its disks from it: the random placement's settings do nothing.
bool placed_at_random(const Params& p) { return p.string("initial_file").empty(); }
bool constant(const Params& p) { return p.choice<Protocol>("protocol") == Protocol::Constant; }
bool annealed(const Params& p) { return p.choice<Protocol>("protocol") == Protocol::Annealed; }
// Cooling only from an amplitude (cool_from > 0) of the constant protocol.
bool cooled(const Params& p) { return constant(p) && p.real("cool_from") > 0.0; }

const double kPaperRadius = 0.1 + 1.0 / std::numbers::sqrt2;
// The shaker's grid is as tall as the loops could lift a disk (one jump a loop): 10^8 loops
// took gigabytes, 10^12 overflowed the count.
constexpr std::int64_t kMostMcLoops = 100000;

// A radius given for a start file that stores its own did nothing, without a word.
void refuse_unused_radius(const PluginContext& ctx, const std::optional<StartFrame>& start) {
  const double radius = ctx.params.real("radius");
  if (!start || !start->radii_stored || radius == kPaperRadius) return;
  // The default's own digits: six would read as another value.
  throw InputError(ctx.param("radius") + ": expected its default " +
                   format_number(kPaperRadius, 17) + " with an initial_file that stores radii (" +
                   start->where + "), got " + format_number(radius, 17));
}
}  // namespace

Schema schema() {
  Schema s;
  // Lengths whose squares stay normal doubles; a bed of 10^6 disks already takes hours a tap.
  s.real("width", 20.0,
         "box width (distance between the side walls), at most 10^6 diameters of the smallest disk")
      .range(1e-50, 1e50)
      .unit("length");
  s.integer("N", 2000, "number of disks").range(1, 1000000);
  s.real("radius", kPaperRadius,
         "disk radius (mean radius when radius_spread > 0); the paper's 0.1 + 1/sqrt2")
      .range(1e-50, 1e50)
      .unit("length");
  s.real("radius_spread", 0.0, "polydispersity: radii uniform in radius * [1 - spread, 1 + spread]")
      .range(0.0, 0.5)
      .only_where("initial_file \"\"", placed_at_random);
  // Random sequential placement jams near 0.547, and the centres of a narrow box reach
  // less than its width: 0.5 is out of reach at the paper's width.
  s.real("initial_fraction", 0.3,
         "area fraction of the random initial placement (sets the height it fills)")
      .min(0.0, true)
      .max(0.45)
      .only_where("initial_file \"\"", placed_at_random);
  s.path("initial_file", std::string(""),
         "start from a frame of this H5MD file (a 2D granpipe frames.h5) instead of a random "
         "placement: its disks are deposited, then tapped; N and width must match it, "
         "radius_spread and initial_fraction are not used, radius only if the file stores "
         "none. Empty: random placement");
  s.integer("initial_frame", -1, "frame of initial_file to start from (-1: the last)").min(-1);
  s.real("delta", 0.01,
         "length of one fall, and arc length of one roll (see roll_measure); at most the "
         "smallest radius")
      .min(0.0, true)
      .max(1.0)
      .unit("length");
  s.choice<RollMeasure>(
      "roll_measure", RollMeasure::CentrePath,
      "what delta measures in a roll: the arc of the rolling disk's centre (radius "
      "r_i + r_s) or of the contact point on the support (radius r_s)");
  s.choice<MoveOrder>(
      "move_order", MoveOrder::Sweeps,
      "sweeps: every unstable disk moves once per sweep, in shuffled order; random: each "
      "move picks a random unstable disk");
  s.choice<SupportUpdate>(
      "support_update", SupportUpdate::Drop,
      "when a disk moves, the disks it supports lose it (drop), or keep it while still "
      "touching to 1e-9 radius and still stable (keep_touching)");
  s.choice<Dilation>("dilation", Dilation::CentreHeight,
                     "a tap multiplies centre heights y (the paper's wording) or heights above the "
                     "lowest centre position y - r_min by A");
  s.integer("mc_loops", kPaperMatchedMcLoops,
            "Monte Carlo loops after each dilation, each trying one jump per disk; the "
            "default puts the order-disorder transition where the paper's 'about 20' do")
      .range(0, kMostMcLoops);
  s.choice<McOrder>("mc_order", McOrder::Index,
                    "order in which a Monte Carlo loop visits the disks: by index, the same in "
                    "every loop, or a fresh random permutation per loop");
  s.choice<Protocol>("protocol", Protocol::Constant,
                     "constant: equilibration then production taps at A; annealed: A ramped up and "
                     "down between anneal_A_min and anneal_A_max (the paper's Fig. 8)");
  s.real("A", 1.1, "tap amplitude of the constant protocol")
      .min(1.0, true)
      .only_where("protocol \"constant\"", constant);
  s.integer("equilibration_taps", 1000, "constant protocol: taps before saving")
      .min(0)
      .only_where("protocol \"constant\"", constant);
  s.integer("production_taps", 1000, "constant protocol: taps after equilibration")
      .min(1)
      .only_where("protocol \"constant\"", constant);
  s.real("cool_from", 0.0,
         "constant protocol: first cool the bed from this amplitude down to A, in steps of "
         "cool_step with cool_taps_per_step taps each, saving nothing (0: no cooling)")
      .min(0.0)
      .only_where("protocol \"constant\"", constant);
  s.real("cool_step", 0.02, "constant protocol: amplitude step of the cooling")
      .min(0.0, true)
      .only_where("cool_from > 0", cooled);
  s.integer("cool_taps_per_step", 2000, "constant protocol: taps at each cooling amplitude")
      .min(1)
      .only_where("cool_from > 0", cooled);
  s.integer("save_every", 10,
            "save every k-th production tap (annealed: every k-th tap of each amplitude step)")
      .min(1);
  s.real("anneal_A_min", 1.0, "annealed protocol: lowest amplitude (1: a tap that does nothing)")
      .min(1.0)
      .only_where("protocol \"annealed\"", annealed);
  s.real("anneal_A_max", 2.0, "annealed protocol: highest amplitude")
      .min(1.0, true)
      .only_where("protocol \"annealed\"", annealed);
  s.integer("anneal_steps", 20, "annealed protocol: amplitude steps per rise or fall")
      .min(1)
      .only_where("protocol \"annealed\"", annealed);
  s.integer("anneal_taps_per_step", 100, "annealed protocol: taps at each amplitude")
      .min(1)
      .only_where("protocol \"annealed\"", annealed);
  s.integer("anneal_cycles", 5,
            "annealed protocol: rise-and-fall cycles (the first rise is kept apart)")
      .min(1)
      .only_where("protocol \"annealed\"", annealed);
  s.integer("replica", 0,
            "independent copy of the run: each value draws other random numbers (sweep it to "
            "average over independent simulations)")
      .min(0);
  return s;
}

namespace {

constexpr double kMaxWidthInDiameters = 1e6;
// A cooling from A + 1e6 down is absurd whatever its step; below that a step too fine is.
constexpr double kWidestCoolingSpan = 1e6;

DepositOptions deposit_options(const Params& p) {
  DepositOptions o;
  o.delta = p.real("delta");
  o.measure = p.choice<RollMeasure>("roll_measure");
  o.order = p.choice<MoveOrder>("move_order");
  o.update = p.choice<SupportUpdate>("support_update");
  return o;
}

// The taps a schedule counts, in doubles: their 64-bit sums and products wrapped round.
void check_tap_counts(const PluginContext& ctx) {
  const Params& p = ctx.params;
  const auto count = [&](const char* name) { return static_cast<double>(p.integer(name)); };
  if (p.choice<Protocol>("protocol") == Protocol::Annealed) {
    check_step_count(
        TapSchedule::annealed_taps(count("anneal_steps"), count("anneal_taps_per_step"),
                                   count("anneal_cycles")),
        ctx.param("anneal_cycles"), "taps",
        "2 anneal_cycles x anneal_steps x anneal_taps_per_step");
    return;
  }
  // The message names the parameter that made the count absurd (production_taps was blamed
  // for an equilibration_taps of 2^63, cool_step for a cool_from of 1e300).
  double cooling = 0.0;
  if (p.real("cool_from") > p.real("A")) {
    const double span = p.real("cool_from") - p.real("A");
    const double levels =
        TapSchedule::cooling_levels(p.real("cool_from"), p.real("cool_step"), p.real("A"));
    check_step_count(levels, ctx.param(span > kWidestCoolingSpan ? "cool_from" : "cool_step"),
                     "cooling levels", "(cool_from - A) / cool_step");
    cooling = levels * count("cool_taps_per_step");
  }
  const std::pair<double, const char*> terms[] = {
      {cooling, "cool_taps_per_step"},
      {count("equilibration_taps"), "equilibration_taps"},
      {count("production_taps"), "production_taps"}};
  const auto largest = *std::max_element(std::begin(terms), std::end(terms));
  check_step_count(cooling + count("equilibration_taps") + count("production_taps"),
                   ctx.param(largest.second), "taps",
                   "cooling levels x cool_taps_per_step + equilibration_taps + production_taps");
}

TapSchedule tap_schedule(const PluginContext& ctx) {
  const Params& p = ctx.params;
  check_tap_counts(ctx);
  if (p.choice<Protocol>("protocol") == Protocol::Constant) {
    const double from = p.real("cool_from");
    if (from == 0.0) {
      return TapSchedule::constant(p.real("A"), p.integer("equilibration_taps"),
                                   p.integer("production_taps"), p.integer("save_every"));
    }
    if (!(from > p.real("A"))) {
      std::ostringstream s;
      s << ctx.param("cool_from")
        << ": expected 0 (no cooling) or an amplitude above A = " << p.real("A") << ", got "
        << from;
      throw InputError(s.str());
    }
    return TapSchedule::cooled_constant(from, p.real("cool_step"), p.integer("cool_taps_per_step"),
                                        p.real("A"), p.integer("equilibration_taps"),
                                        p.integer("production_taps"), p.integer("save_every"));
  }
  if (!(p.real("anneal_A_max") > p.real("anneal_A_min"))) {
    std::ostringstream s;
    s << ctx.param("anneal_A_max")
      << ": expected more than anneal_A_min = " << p.real("anneal_A_min") << ", got "
      << p.real("anneal_A_max");
    throw InputError(s.str());
  }
  return TapSchedule::annealed(p.real("anneal_A_min"), p.real("anneal_A_max"),
                               p.integer("anneal_steps"), p.integer("anneal_taps_per_step"),
                               p.integer("anneal_cycles"), p.integer("save_every"));
}

std::vector<double> disk_radii(const Params& p, RandomStream rng) {
  const auto n = static_cast<std::size_t>(p.integer("N"));
  const double r = p.real("radius"), spread = p.real("radius_spread");
  std::vector<double> radii(n, r);
  if (spread > 0.0) {
    for (double& ri : radii) ri = r * (1.0 + spread * (2.0 * rng.uniform() - 1.0));
  }
  return radii;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Seeds replica_seeds(const PluginContext& ctx) {
  return ctx.seeds.derive("replica", static_cast<std::uint64_t>(ctx.params.integer("replica")));
}

// The paper's start: disks of the given radii placed at random without overlap.
DiskPacking random_placement(const PluginContext& ctx, const Seeds& seeds) {
  const Params& p = ctx.params;
  const std::vector<double> radii = disk_radii(p, seeds.stream("radii"));
  const double width = p.real("width");
  const double r_max = *std::max_element(radii.begin(), radii.end());
  if (2.0 * r_max > width) {
    std::ostringstream s;
    // The box is what a --set usually changes; the radius keeps the paper's value.
    s << ctx.param("width") << ": expected at least the largest disk diameter "
      << format_apart(2.0 * r_max, width) << " (radius " << p.real("radius") << ", radius_spread "
      << p.real("radius_spread") << "), got " << format_apart(width, 2.0 * r_max);
    throw InputError(s.str());
  }
  // The simulation's grids have a cell per disk across the width: bound them before
  // they are allocated.
  const double d_min = 2.0 * *std::min_element(radii.begin(), radii.end());
  if (width > kMaxWidthInDiameters * d_min) {
    std::ostringstream s;
    s << ctx.param("width") << ": expected at most " << kMaxWidthInDiameters
      << " diameters of the smallest disk (" << d_min << "), got " << width;
    throw InputError(s.str());
  }
  double area = 0.0;
  for (double ri : radii) area += std::numbers::pi * ri * ri;
  const double height = std::max(area / (width * p.real("initial_fraction")), 2.0 * r_max);
  RandomStream placement = seeds.stream("placement");
  try {
    return place_at_random(width, height, radii, placement, ctx.param("N"));
  } catch (const SpreadTooThin& e) {
    throw InputError(ctx.param("initial_fraction") + ": " + e.what());
  }
}

// A saved bed to continue from, e.g. one cooled slowly through the transition.
DiskPacking saved_bed(const PluginContext& ctx, const StartFrame& start) {
  const Params& p = ctx.params;
  const std::string file = p.string("initial_file");
  DiskPacking bed = DiskPacking::from_frame(start.frame, start.where);
  if (static_cast<std::int64_t>(bed.size()) != p.integer("N")) {
    throw InputError(ctx.param("N") + ": expected the " + std::to_string(bed.size()) +
                     " disks of " + file + ", got " + std::to_string(p.integer("N")));
  }
  if (std::abs(bed.width - p.real("width")) > 1e-12 * bed.width) {
    std::ostringstream s;
    s.precision(17);
    s << ctx.param("width") << ": expected the box width of " << file << " (" << bed.width
      << "), got " << p.real("width");
    throw InputError(s.str());
  }
  return bed;
}

}  // namespace

TapSource::TapSource(const PluginContext& ctx)
    : progress_(ctx.progress),
      deposition_rng_(replica_seeds(ctx).stream("deposition")),
      tap_rng_(replica_seeds(ctx).stream("tap")),
      schedule_(tap_schedule(ctx)),
      shaker_(static_cast<int>(ctx.params.integer("mc_loops")),
              ctx.params.choice<Dilation>("dilation"), ctx.params.choice<McOrder>("mc_order")),
      amplitude_param_(ctx.param(annealed(ctx.params)               ? "anneal_A_max"
                                 : ctx.params.real("cool_from") > 0 ? "cool_from"
                                                                    : "A")) {
  const Params& p = ctx.params;
  const std::optional<StartFrame> start = read_start_frame(ctx, p.real("radius"));
  refuse_unused_radius(ctx, start);
  packing_ = start ? saved_bed(ctx, *start) : random_placement(ctx, replica_seeds(ctx));
  if (p.real("delta") > packing_.min_radius()) {
    std::ostringstream s;
    s << ctx.param("delta") << ": expected at most the smallest radius " << packing_.min_radius()
      << ", got " << p.real("delta");
    throw InputError(s.str());
  }
  // A fall of delta must move a disk: below 1e-9 of the bed's size it is lost in the
  // rounding of the coordinates (1e-320 moved nothing, and the deposition never ended).
  const double size = std::max(packing_.width, packing_.top());
  if (p.real("delta") < 1e-9 * size) {
    throw InputError(ctx.param("delta") + ": expected at least 1e-9 of the bed's size (" +
                     format_number(size) + "), below which a fall is lost in the rounding of " +
                     "the coordinates, got " + format_number(p.real("delta")));
  }
  const auto protocol = p.choice<Protocol>("protocol");
  if (protocol == Protocol::Constant && p.integer("production_taps") < p.integer("save_every")) {
    throw InputError(ctx.param("production_taps") + ": expected at least save_every = " +
                     std::to_string(p.integer("save_every")) + " (else nothing is saved), got " +
                     std::to_string(p.integer("production_taps")));
  }
  if (protocol == Protocol::Annealed &&
      p.integer("anneal_taps_per_step") < p.integer("save_every")) {
    throw InputError(ctx.param("anneal_taps_per_step") + ": expected at least save_every = " +
                     std::to_string(p.integer("save_every")) + " (else nothing is saved), got " +
                     std::to_string(p.integer("anneal_taps_per_step")));
  }
  deposit_ = std::make_unique<Deposit>(packing_, deposit_options(p));
}

void TapSource::deposit() {
  const auto t0 = std::chrono::steady_clock::now();
  deposit_->run(deposition_rng_);
  deposition_seconds_ += seconds_since(t0);
}

bool TapSource::next(Frame& frame) {
  if (!started_) {
    deposit();
    started_ = true;
  }
  while (tap_ < schedule_.total()) {
    const TapStep step = schedule_.at(++tap_);
    const auto t0 = std::chrono::steady_clock::now();
    try {
      shaker_.tap(packing_, step.amplitude, tap_rng_);
      deposit_->reset();
      tap_seconds_ += seconds_since(t0);
      deposit();
    } catch (const SpreadTooThin& e) {
      throw InputError(amplitude_param_ + ": tap " + std::to_string(tap_) + " of amplitude " +
                       format_number(step.amplitude) + ": " + e.what());
    }
    progress_.advance(1.0);
    if (step.save) {
      packing_.to_frame(frame);
      frame.step = tap_;
      frame.time = static_cast<double>(tap_);  // the scene's clock counts taps
      frame.set_observable(tap_property(), tap_);
      frame.set_observable(cycle_property(), step.cycle);
      frame.set_observable(amplitude_property(), step.amplitude);
      return true;
    }
  }
  return false;
}

void TapSource::finish(Results& results) {
  const DepositStats& d = deposit_->stats();
  const ShakeStats& m = shaker_.stats();
  const auto moves = static_cast<double>(d.moves());
  results.add_scalar(
      "moves", moves, std::nan(""), "",
      "falls and rolls of the deposition pseudo-dynamics, initial deposition included");
  results.add_scalar("falls", static_cast<double>(d.falls), std::nan(""), "", "free falls");
  results.add_scalar("rolls", static_cast<double>(d.rolls), std::nan(""), "", "rolls");
  results.add_scalar("taps", static_cast<double>(tap_), std::nan(""), "", "taps done");
  results.add_scalar(
      "mc_acceptance",
      m.trials ? static_cast<double>(m.accepted) / static_cast<double>(m.trials) : std::nan(""),
      std::nan(""), "",
      "fraction of accepted Monte Carlo jumps during taps; NaN without a jump (mc_loops 0)");
  results.add_scalar("deposition_seconds", deposition_seconds_, std::nan(""), "s",
                     "wall time spent depositing");
  results.add_scalar("tap_seconds", tap_seconds_, std::nan(""), "s",
                     "wall time spent dilating and shaking");
  results.add_scalar("seconds", deposition_seconds_ + tap_seconds_, std::nan(""), "s",
                     "wall time of the simulation");
  results.add_scalar("moves_per_second",
                     deposition_seconds_ > 0 ? moves / deposition_seconds_ : 0.0, std::nan(""),
                     "1/s", "deposition speed");
}

}  // namespace granpipe::disks2d_tap
