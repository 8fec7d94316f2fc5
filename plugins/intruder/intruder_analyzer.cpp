#include "intruder_analyzer.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/bottom_wall.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/loaded_pair_contacts.hpp"

namespace granpipe::intruder {

namespace {

// Mass-weighted mean of a per-particle value over the bed (every particle but `skip`).
// Mass ∝ density r³; the frame carries no density, and the bed's particles share one
// species (require_one_bed_species), so r³ weights them. Summed over the bed itself: the
// sum over all less the intruder's term cancelled when the intruder outweighs the bed (a bed
// of radius 1e-5 beside an intruder of 1 had the velocity 0 for 2.8e-5).
double bed_mean(const Eigen::ArrayXd& weight, const Eigen::ArrayXd& value, Eigen::Index skip) {
  const Eigen::Index n = weight.size(), after = n - skip - 1;
  const double weighted =
      (weight.head(skip) * value.head(skip)).sum() + (weight.tail(after) * value.tail(after)).sum();
  return weighted / (weight.head(skip).sum() + weight.tail(after).sum());
}

// The bed's centre of mass weights its particles by r^3, which is their mass only when they
// share a density: a bed of two species (densities 1.91 and 20) gave a height 8 too low.
void require_one_bed_species(const Frame& f, Eigen::Index intruder, const std::string& where) {
  const Eigen::Index first = intruder == 0 ? 1 : 0;
  const auto& species = f.species();
  for (Eigen::Index i = first + 1; i < f.size(); ++i) {
    if (i == intruder || species[i] == species[first]) continue;
    throw InputError(where + ": expected a bed of one species (the frame carries no densities " +
                     "to weight its centre of mass by), got species " +
                     std::to_string(species[first]) + " (particle " + std::to_string(first) +
                     ") and " + std::to_string(species[i]) + " (particle " + std::to_string(i) +
                     ")");
  }
}

}  // namespace

Eigen::Index find_intruder(const Frame& f, const std::string& where) {
  Eigen::Index big = 0;
  const double largest = f.radius().maxCoeff(&big);
  // Radii equal but for rounding (a file's float32 radii) count as equal.
  const double equal = largest * (1.0 - kSameRadius);
  const auto ties = (f.radius() >= equal).count();
  if (ties > 1) {
    throw InputError(where + ": expected an intruder (one particle larger than every other), got " +
                     std::to_string(ties) + " particles of the largest radius " +
                     format_number(largest) + " (a bed without an intruder?)");
  }
  // A species of its own names the intruder, whatever the bed's radii. Else, in a
  // polydisperse bed the largest grain is one of the bed, its tail (radii 0.45 to 0.55 gave
  // "the intruder" r = 0.5499 beside 0.5474, exit 0), unless it stands apart.
  const auto& species = f.species();
  if ((species == species[big]).count() == 1) return big;
  double second = 0.0;
  for (Eigen::Index i = 0; i < f.size(); ++i)
    if (i != big) second = std::max(second, f.radius()[i]);
  const double smallest = f.radius().minCoeff();
  if (!(largest - second > second - smallest)) {
    throw InputError(where + ": expected an intruder (one particle larger than every other, " +
                     "of a species of its own or by more than the bed's own radii spread), got " +
                     "a largest radius " + format_number(largest) + " beside the bed's " +
                     format_number(smallest) + " to " + format_number(second) +
                     " (a polydisperse bed without an intruder?)");
  }
  return big;
}

// The rows joining a particle to the base with a non-zero normal force (every base row when
// the table has none).
long loaded_base_contacts(const Frame& f) {
  const IndexArray& j = f.contact_j();
  const Coordinates* force =
      f.contacts->has("normal_force") ? &f.contacts->get<Coordinates>("normal_force") : nullptr;
  long count = 0;
  for (Eigen::Index c = 0; c < j.size(); ++c) {
    if (j[c] != partner::wall(Wall::ZLow)) continue;
    if (!force || force->row(c).matrix().norm() > 0.0) ++count;
  }
  return count;
}

BedState measure_bed(const Frame& f, const std::string& where) {
  const Eigen::Index n = f.size();
  if (n < 2) {
    throw InputError(where + ": expected an intruder and a bed (2 particles or more), got " +
                     std::to_string(n));
  }
  // (Without a base the stage, which follows the base contacts, was "expansion" forever.)
  require_bottom_wall(f.container, 2,
                      where + ": expected a base (a wall at the bottom along z) to measure " +
                          "heights and the stage from");
  const Eigen::Index big = find_intruder(f, where);
  require_one_bed_species(f, big, where);
  const double base = f.container.wall_at(2, 0);
  const Eigen::ArrayXd weight = f.radius().cube();
  BedState s;
  s.intruder_height = f.position()(big, 2) - base;
  s.bed_height = bed_mean(weight, f.position().col(2), big) - base;
  if (f.has("velocity")) {
    const auto& v = f.table<double>("velocity");
    s.intruder_velocity = v(big, 2);
    s.bed_velocity = bed_mean(weight, v.col(2), big);
  }
  if (f.contacts) {  // without a contact table: no contacts, the expansion stage
    // Rows of zero normal force (another code's neighbour pairs) touch nothing: counted,
    // the coordination read 3.31 where force_network's read 0.
    const auto pairs = static_cast<double>(loaded_pair_contacts(f, where).size());
    s.coordination = 2.0 * pairs / static_cast<double>(n);
    s.base_contacts = loaded_base_contacts(f);
  }
  s.stage = s.base_contacts > 0 ? Stage::Compression : Stage::Expansion;
  return s;
}

IntruderAnalyzer::IntruderAnalyzer(const PluginContext& ctx)
    : per_frame_(ctx.stream_table(
          "per_frame",
          Table({"frame", "time", "cycles", "intruder_height", "bed_height", "intruder_velocity",
                 "bed_velocity", "coordination", "base_contacts", "stage"},
                "intruder and bed centre-of-mass heights above the base and vertical velocities, "
                "mean coordination number, particles touching the base, stage (1 compression, "
                "0 expansion), per frame; cycles = drive periods when the source counts them",
                {"", "time", "", "length", "length", "length/time", "length/time", "", "", ""}))),
      transitions_({"time", "cycles", "stage"},
                   "moments the stage changes (midpoint of the two frames): stage 0 = lift-off "
                   "(expansion begins), 1 = impact (compression begins)") {}

FrameContent IntruderAnalyzer::needs() const {
  FrameContent c{.dim = 3, .contacts = true};
  c.columns.push_back(*find_standard("velocity", Scope::Particle));
  return c;
}

void IntruderAnalyzer::consume(const Frame& frame, FrameCache&) {
  const BedState s = measure_bed(frame, "frame " + std::to_string(frames_));
  const double cycles = frame.real_observable("cycles").value_or(std::nan(""));
  if (frames_ > 0 && s.stage != last_stage_) {
    transitions_.add_row({0.5 * (last_time_ + frame.time), 0.5 * (last_cycles_ + cycles),
                          static_cast<double>(s.stage)});
  }
  per_frame_.add_row({static_cast<double>(frames_), frame.time, cycles, s.intruder_height,
                      s.bed_height, s.intruder_velocity, s.bed_velocity, s.coordination,
                      static_cast<double>(s.base_contacts), static_cast<double>(s.stage)});
  last_time_ = frame.time;
  last_cycles_ = cycles;
  last_stage_ = s.stage;
  ++frames_;
}

void IntruderAnalyzer::finish(Results& results) {
  results.add_table("per_frame", per_frame_.table());
  results.add_table("transitions", transitions_);
  // Against the drive's cycles (the paper's intruder height per cycle) when the source
  // counts them, else against time (frames read back without a drive).
  const bool by_cycle = std::isfinite(last_cycles_);
  results.add_plot("heights", {.table = "per_frame",
                               .x = by_cycle ? "cycles" : "time",
                               .y = {"intruder_height", "bed_height"},
                               .xlabel = by_cycle ? "drive cycles" : "time",
                               .ylabel = "height above the base",
                               .title = "intruder and bed centre of mass"});
  results.add_plot("velocities", {.table = "per_frame",
                                  .x = "time",
                                  .y = {"intruder_velocity", "bed_velocity"},
                                  .xlabel = "time",
                                  .ylabel = "vertical velocity",
                                  .title = "intruder and bed centre of mass"});
  results.add_scalar("frames", static_cast<double>(frames_), std::nan(""), "", "frames measured");
}

}  // namespace granpipe::intruder
