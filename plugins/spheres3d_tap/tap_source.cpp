#include "tap_source.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "granpipe/container.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/start_frame.hpp"
#include "granpipe/step_count.hpp"
#include "saved_packing.hpp"

namespace granpipe::spheres3d_tap {

namespace {

Property tap_property() {
  return {"tap", Scope::Frame, ValueType::Integer, 1, "", "tap number (0: the deposition)"};
}
Property epsilon_property() {
  return {"epsilon", Scope::Frame, ValueType::Real,
          1,         "",           "dilation of the tap, z -> z (1 + epsilon)"};
}
Property mean_height_property() {
  return {"mean_height", Scope::Frame, ValueType::Real, 1, "length", "<Z>, the mean centre height"};
}
Property leg_property() {
  return {"leg", Scope::Frame, ValueType::Integer,
          1,     "",           "leg of the ramp protocol (0 up, 1 down, 2 up, ...), -1 constant"};
}
Property trials_property() {
  return {"mc_trials", Scope::Frame, ValueType::Integer,
          1,           "",           "Monte Carlo trial moves of the tap"};
}
Property acceptance_property() {
  return {"mc_acceptance",
          Scope::Frame,
          ValueType::Real,
          1,
          "",
          "accepted fraction of the tap's trial moves"};
}

RedepositionOptions redeposition_options(const Params& p) {
  RedepositionOptions o;
  o.move = TrialMove(p.real("d_max") * p.real("radius"), p.real("theta0"));
  o.eta = p.real("eta");
  o.check_moves = p.integer("check_moves");
  o.max_checks = p.integer("max_checks");
  return o;
}

TapBox tap_box(const PluginContext& ctx) {
  const Params& p = ctx.params;
  return {p.real("side") * p.real("radius"), p.real("radius"), p.choice<Sides>("sides")};
}

// How epsilon goes: one value, or stepped ramps of sqrt(epsilon) (parameter protocol).
enum class Protocol : std::uint8_t { Constant, Ramp };
ChoiceNames<Protocol> choice_names(Protocol) {
  return {{"constant", Protocol::Constant}, {"ramp", Protocol::Ramp}};
}

EpsilonProtocol epsilon_protocol(const PluginContext& ctx) {
  const Params& p = ctx.params;
  if (p.choice<Protocol>("protocol") == Protocol::Constant) {
    check_step_count(static_cast<double>(p.integer("taps")), ctx.param("taps"), "taps", "taps");
    return EpsilonProtocol::constant(p.real("epsilon"), p.integer("taps"));
  }
  const double lo = p.real("ramp_root_min"), hi = p.real("ramp_root_max"),
               step = p.real("ramp_root_step");
  if (!(hi >= lo + step)) {
    std::ostringstream s;
    s << ctx.param("ramp_root_max")
      << ": expected at least ramp_root_min + ramp_root_step = " << lo + step << " (one step), got "
      << hi;
    throw InputError(s.str());
  }
  // The ramp turns at the last whole step: a top between two steps was never reached, and
  // said nothing (0.1 to 0.25 in steps of 0.1 turned at 0.2).
  const double steps = std::round((hi - lo) / step);
  if (std::abs(lo + steps * step - hi) > 1e-9 * step) {
    std::ostringstream s;
    s << ctx.param("ramp_root_max")
      << ": expected ramp_root_min + a whole number of ramp_root_step (" << lo << " + k " << step
      << "), got " << hi << ": the ramp would turn at "
      << lo + std::floor((hi - lo) / step + 1e-9) * step;
    throw InputError(s.str());
  }
  if (hi * hi > 1.0) {
    std::ostringstream s;
    s << ctx.param("ramp_root_max")
      << ": expected at most 1 (epsilon at most 1, as for epsilon), got " << hi;
    throw InputError(s.str());
  }
  const double legs = static_cast<double>(p.integer("ramp_legs"));
  check_step_count(
      EpsilonProtocol::ramp_taps(steps, static_cast<double>(p.integer("ramp_taps_per_step")), legs),
      ctx.param("ramp_taps_per_step"), "taps",
      "ramp_taps_per_step x the values of sqrt(epsilon) over ramp_legs legs");
  return EpsilonProtocol::ramp(lo, hi, step, p.integer("ramp_taps_per_step"),
                               static_cast<int>(legs));
}

double mean_height(const std::vector<Eigen::Vector3d>& centres) {
  double sum = 0.0;
  for (const auto& c : centres) sum += c.z();
  return centres.empty() ? std::nan("") : sum / static_cast<double>(centres.size());
}

Seeds replica_seeds(const PluginContext& ctx) {
  return ctx.seeds.derive("replica", static_cast<std::uint64_t>(ctx.params.integer("replica")));
}

}  // namespace

Schema schema() {
  const auto constant = [](const Params& p) {
    return p.choice<Protocol>("protocol") == Protocol::Constant;
  };
  const auto ramp = [](const Params& p) {
    return p.choice<Protocol>("protocol") == Protocol::Ramp;
  };
  Schema s;
  s.integer("N", 4096, "number of spheres (the paper's 4096)").range(1, 1000000);
  s.real("radius", 1.0, "sphere radius R").range(1e-50, 1e50).unit("length");
  // Narrower than two diameters, the box holds a column: a sphere may touch two images of
  // one sphere, or be wedged between a sphere and the far wall, which the deposition's roll
  // geometry does not model (it left overlapping spheres, or one through a wall, exit 0).
  // At exactly two diameters a sphere touches one neighbour on both sides, a pair no contact
  // table holds once: the analyzers' neighbour search refused such a box after the
  // deposition, though validation had passed it.
  s.real("side", 32.0,
         "side L of the square box, in units of R (the paper's 32); at least 4.1, a little more "
         "than two diameters")
      .range(4.1, 1e4);
  s.choice<Sides>("sides", Sides::Periodic,
                  "lateral sides: periodic (P.B.C.) or fixed walls (F.B.C.); the paper's initial "
                  "packing fraction 58.4 % is the periodic deposition's");
  s.path("initial_file", std::string(""),
         "start from a frame of this H5MD file (e.g. a frames.h5 of this source) instead of a "
         "deposition; N, radius, side and sides must match it. Empty: deposit");
  s.integer("initial_frame", -1, "frame of initial_file to start from (-1: the last)").min(-1);
  s.boolean("continue_count", false,
            "with initial_file: count taps on from the saved frame's step (its tap), so that a run "
            "split over sessions keeps one tap axis, save schedule and ramp; taps is then the "
            "last tap, not the number after the start");
  s.choice<Protocol>("protocol", Protocol::Constant,
                     "constant: taps taps at epsilon; ramp: sqrt(epsilon) stepped from "
                     "ramp_root_min to ramp_root_max and back (the paper's Fig. 4)");
  s.real("epsilon", 0.05, "constant protocol: tap dilation, centre heights z -> z (1 + epsilon)")
      .range(0.0, 1.0)
      .only_where("protocol \"constant\"", constant);
  s.integer("taps", 100, "constant protocol: taps after the start")
      .min(0)
      .only_where("protocol \"constant\"", constant);
  s.real("ramp_root_min", 0.025, "ramp protocol: lowest sqrt(epsilon)")
      .range(0.0, 1.0)
      .only_where("protocol \"ramp\"", ramp);
  s.real("ramp_root_max", 0.4,
         "ramp protocol: highest sqrt(epsilon), reached from ramp_root_min in whole steps")
      .range(0.0, 1.0)
      .only_where("protocol \"ramp\"", ramp);
  s.real("ramp_root_step", 0.025, "ramp protocol: step of sqrt(epsilon) (the paper's 0.025)")
      .range(1e-6, 1.0)
      .only_where("protocol \"ramp\"", ramp);
  s.integer("ramp_taps_per_step", 4000, "ramp protocol: taps at each value (the paper's 4000)")
      .min(1)
      .only_where("protocol \"ramp\"", ramp);
  s.integer("ramp_legs", 3,
            "ramp protocol: legs, alternately up and down (the paper's up, down, up: 3)")
      .range(1, 1000)
      .only_where("protocol \"ramp\"", ramp);
  s.integer("save_every", 10,
            "save every k-th tap, the start (tap 0), the last tap and, in a ramp, the last tap "
            "at each value")
      .min(1);
  s.boolean("log_frames", true, "also save taps spaced evenly in log(tap), ten per decade");
  s.boolean("save_start", true,
            "save tap 0 (the deposition or the saved packing); false: only tapped packings, e.g. "
            "a sweep over taps with shared seeds whose points each measure one stage");
  s.real("d_max", 0.2, "largest Monte Carlo displacement, in units of R (the paper's R/5)")
      .range(1e-6, 2.0);
  s.real("theta0", std::numbers::pi / 4.0,
         "width of the polar-angle density exp(-(theta/theta0)^2) of a trial move, theta from "
         "straight down, a density in theta (the paper's pi/4)")
      .range(1e-3, 100.0)
      .unit("rad");
  s.real("eta", 1e-6,
         "a tap's redeposition stops when <Z> changes by less than this fraction between two "
         "checks")
      .range(0.0, 1.0);
  // Bounded as the taps are: 2^63 trials a check never ended the first tap.
  s.integer("check_moves", 0,
            "trial moves between two checks of <Z> (0: N, one sweep, and at least 64); at most "
            "1e10 (minutes a check)")
      .range(0, 1e10);
  s.integer("max_checks", 100000,
            "a tap's redeposition stops after this many checks even if <Z> still moves (such taps "
            "are counted in unconverged_taps); at most 1e9")
      .range(1, 1e9);
  s.integer("replica", 0, "independent copy of the run (sweep it to average over realizations)")
      .min(0);
  return s;
}

TapSource::TapSource(const PluginContext& ctx)
    : progress_(ctx.progress),
      box_(tap_box(ctx)),
      deposition_rng_(replica_seeds(ctx).stream("deposition")),
      tap_rng_(replica_seeds(ctx).derive("tap").seed()),
      redeposition_(box_, redeposition_options(ctx.params)),
      schedule_{ctx.params.integer("save_every"), ctx.params.boolean("log_frames"),
                ctx.params.boolean("save_start")},
      protocol_(epsilon_protocol(ctx)),
      continue_count_(ctx.params.boolean("continue_count")),
      seeds_(replica_seeds(ctx)),
      n_(ctx.params.integer("N")),
      eta_param_(ctx.param("eta")),
      per_tap_(ctx.stream_table(
          "per_tap", Table({"tap", "epsilon", "leg", "mean_height", "mc_trials", "mc_acceptance"},
                           "every tap: its epsilon and ramp leg, <Z> after redeposition, trial "
                           "moves, accepted fraction",
                           {"", "", "", "length", "", ""}))) {
  if (!schedule_.start && protocol_.taps() == 0) {
    throw InputError(ctx.param("save_start") +
                     ": expected true for a run of no tap (taps 0), got false: the run would "
                     "save no frame");
  }
  const std::int64_t check_moves = ctx.params.integer("check_moves");
  const std::int64_t fewest = Redeposition::fewest_trials_per_check(static_cast<std::size_t>(n_));
  if (check_moves > 0 && check_moves < fewest) {
    throw InputError(ctx.param("check_moves") + ": expected 0 (one sweep) or at least " +
                     std::to_string(fewest) + " trials (N, and at least 64), got " +
                     std::to_string(check_moves) +
                     ": a shorter check sees a few spheres' moves, and a run of refused ones "
                     "passes for settled");
  }
  // <Z> is at least R: a rule that fails there fails every packing, and is refused when the
  // pipeline is checked (eta 1 was refused at the first tap, its folder made and marked).
  check_stopping_rule(box_.radius);
  const std::optional<StartFrame> start = read_start_frame(ctx, box_.radius);
  // Without a file it would change nothing: a start meant to continue a run would
  // silently begin a new one.
  if (!start && continue_count_) {
    throw InputError(ctx.param("continue_count") +
                     ": expected it only with initial_file (counting on from a saved frame's "
                     "tap), got true without one");
  }
  if (start) {
    saved_ = read_saved_packing(*start, box_, static_cast<long>(n_));
    if (continue_count_) check_saved_tap(*saved_);
  }
}

FrameContent TapSource::content() const {
  return {.dim = 3,
          .columns = {tap_property(), epsilon_property(), leg_property(), mean_height_property(),
                      trials_property(), acceptance_property()}};
}

void TapSource::start() {
  if (saved_) {
    centres_ = std::move(saved_->centres);
    if (continue_count_) {
      tap_ = saved_->step;
      progress_.skip(static_cast<double>(tap_));
      // A stream of its own for each start, so that a continuation does not replay the
      // random numbers its first part began with.
      tap_rng_ = FastRandomStream(seeds_.derive("tap", static_cast<std::uint64_t>(tap_)).seed());
    }
    return;
  }
  Deposition deposition(box_);
  deposition.drop_random(static_cast<int>(n_), deposition_rng_);
  centres_ = deposition.centres();
}

// A tap that stops before its packing could move would lift the packing by 1 + epsilon
// and leave it there, counted as settled (d_max 1e-6 or eta 1 did, exit 0). Heights only
// grow on dilation, so what holds for the start holds for every tap.
void TapSource::check_stopping_rule(double height) const {
  const double change = redeposition_.largest_height_change(static_cast<std::size_t>(n_));
  const double threshold = redeposition_.eta() * height;
  if (change > threshold) return;
  throw InputError(eta_param_ + ": expected a stopping rule a settling packing can pass, got " +
                   "one every tap meets at its first check: between two checks <Z> moves by " +
                   format_number(change / box_.radius) + " R at most (check_moves trials of " +
                   "d_max), not above eta <Z> = " + format_number(threshold / box_.radius) + " R" +
                   (height == box_.radius ? " at the least (<Z> >= R)" : "") +
                   "; lower eta, or raise d_max or check_moves");
}

// The tap to count on from: a frame this source saved, whose tap is its step, before the
// last tap (a later one would leave nothing to do, a negative one count through 0 again).
void TapSource::check_saved_tap(const SavedPacking& saved) const {
  if (!saved.tap) {
    throw InputError(saved.at +
                     ": expected a frame with a tap observable (a frames.h5 of spheres3d_tap) "
                     "for continue_count to count on from, got none (step " +
                     std::to_string(saved.step) + ")");
  }
  if (*saved.tap != saved.step) {
    throw InputError(saved.at +
                     ": expected the step equal to the tap for continue_count, got tap " +
                     std::to_string(*saved.tap) + " at step " + std::to_string(saved.step));
  }
  const std::int64_t last = protocol_.taps();
  if (saved.step < 0 || saved.step >= last) {
    throw InputError(saved.at + ": expected a saved tap from 0 to " + std::to_string(last - 1) +
                     " for continue_count (the run counts to tap " + std::to_string(last) +
                     "), got tap " + std::to_string(saved.step));
  }
  check_saved_protocol(saved);
}

// The continued run's protocol must be the one that made the saved tap: another epsilon
// (or a ramp for a constant run) labelled the saved packing with the new protocol's values,
// and parts read as one run joined two protocols into one series (exit 0). Tap 0, the
// deposition, was made by none; nor says a continued part's start frame written before
// 2026-11-28 (labelled as a deposition, epsilon 0 and leg -1, at its saved tap) which.
void TapSource::check_saved_protocol(const SavedPacking& saved) const {
  if (saved.step == 0) return;
  if (saved.epsilon == 0.0 && saved.leg == -1) return;
  const EpsilonAt here = protocol_.at(saved.step);
  const bool same_epsilon =
      !saved.epsilon || std::abs(*saved.epsilon - here.epsilon) <= 1e-12 * here.epsilon;
  const bool same_leg = !saved.leg || *saved.leg == here.leg;
  if (same_epsilon && same_leg) return;
  throw InputError(saved.at + ": expected the tap continued to have been made by this run's " +
                   "protocol (epsilon " + format_number(here.epsilon) + ", leg " +
                   std::to_string(here.leg) + " at tap " + std::to_string(saved.step) +
                   "), got epsilon " + (saved.epsilon ? format_number(*saved.epsilon) : "none") +
                   ", leg " + (saved.leg ? std::to_string(*saved.leg) : "none") +
                   " (continue_count continues a run: give it the parameters it ran with)");
}

void TapSource::to_frame(Frame& frame, const TapStats& stats, const EpsilonAt& e) const {
  const auto n = static_cast<Eigen::Index>(centres_.size());
  frame.resize(n, 3);
  double top = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    frame.position().row(k) = centres_[static_cast<std::size_t>(k)].transpose();
    top = std::max(top, centres_[static_cast<std::size_t>(k)].z() + box_.radius);
  }
  frame.radius().setConstant(box_.radius);
  frame.container = box_.container(top);
  frame.step = tap_;
  frame.time = static_cast<double>(tap_);  // the scene's clock counts taps
  frame.set_observable(tap_property(), tap_);
  frame.set_observable(epsilon_property(), e.epsilon);
  frame.set_observable(leg_property(), static_cast<std::int64_t>(e.leg));
  frame.set_observable(mean_height_property(), mean_height(centres_));
  frame.set_observable(trials_property(), stats.trials);
  frame.set_observable(acceptance_property(), stats.trials ? static_cast<double>(stats.accepted) /
                                                                 static_cast<double>(stats.trials)
                                                           : std::nan(""));
}

void TapSource::record(const TapStats& stats, const EpsilonAt& e) {
  const double acceptance =
      stats.trials ? static_cast<double>(stats.accepted) / static_cast<double>(stats.trials)
                   : std::nan("");
  per_tap_.add_row({static_cast<double>(tap_), e.epsilon, static_cast<double>(e.leg),
                    mean_height(centres_), static_cast<double>(stats.trials), acceptance});
  unconverged_ += !stats.converged;
  trials_ += static_cast<double>(stats.trials);
}

bool TapSource::next(Frame& frame) {
  while (!started_ || tap_ < protocol_.taps()) {
    const auto t0 = std::chrono::steady_clock::now();
    TapStats stats;
    EpsilonAt e{0.0, -1, false};  // the start: no tap
    const bool starting = !started_;
    if (starting) {
      tap_ = 0;
      start();
      check_stopping_rule(mean_height(centres_));
      started_ = true;
      // A continuation starts at the saved tap: its epsilon and leg, not a deposition's
      // (0, -1), which a part read alone grouped with the deposition. No trial ran here.
      if (tap_ > 0) e = protocol_.at(tap_);
    } else {
      ++tap_;
      e = protocol_.at(tap_);
      stats = redeposition_.tap(centres_, e.epsilon, tap_rng_);
      progress_.advance(1.0);
    }
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    record(stats, e);
    // The last tap too: its packing is the run's result, and the one a continuation starts
    // from (taps 120 in steps of 50 left the last 20 unsaved).
    const bool last = !starting && tap_ == protocol_.taps();
    if ((starting ? schedule_.start : schedule_.saves(tap_)) || (e.leg >= 0 && e.ends_step) ||
        last) {
      to_frame(frame, stats, e);
      return true;
    }
  }
  return false;
}

void TapSource::finish(Results& results) {
  results.add_table("per_tap", per_tap_.table());
  results.add_scalar("unconverged_taps", static_cast<double>(unconverged_), std::nan(""), "",
                     "taps whose redeposition reached max_checks before <Z> settled to eta, or "
                     "moved no sphere of the dilated packing");
  results.add_scalar("seconds", seconds_, std::nan(""), "s", "wall time of deposition and taps");
  results.add_scalar("mc_trials", trials_, std::nan(""), "", "Monte Carlo trial moves of all taps");
  results.add_scalar("final_mean_height", mean_height(centres_), std::nan(""), "length",
                     "<Z>, the mean centre height, after the last tap");
}

}  // namespace granpipe::spheres3d_tap
