#include "arches_analyzer.hpp"

#include <cmath>
#include <set>
#include <string>

#include "arch_statistics.hpp"
#include "contact_census.hpp"
#include "granpipe/contacts_by_distance.hpp"
#include "mutual_stability.hpp"
#include "support_count.hpp"
#include "svg_writer.hpp"

namespace granpipe::arches {

namespace {

const std::vector<std::string> kPerFrameColumns = {"frame",
                                                   "tap",
                                                   "cycle",
                                                   "arches_per_particle",
                                                   "p1_over_N",
                                                   "p2_over_N",
                                                   "z_support_eq4",
                                                   "z_support_direct",
                                                   "base_fraction",
                                                   "missing_supports_per_particle",
                                                   "non_supporting_contact_fraction"};

std::string frame_name(long index, const Frame& frame) {
  std::string name = "arches: frame " + std::to_string(index);
  if (const auto tap = frame.integer_observable("tap")) {
    name += " (tap " + std::to_string(*tap) + ")";
  }
  return name;
}

}  // namespace

Schema schema() {
  Schema s;
  declare_contact_tolerance(s);
  s.real("span_bin", 0.05, "bin width of the span distributions n_s(x)")
      .min(0.0, true)
      .unit("mean disk diameters");
  s.integers("span_sizes", std::vector<std::int64_t>{2, 3, 4},
             "arch sizes s whose span distribution n_s(x) is reported (all arches always are)")
      .min(2);
  s.integer("svg_frames", 1,
            "how many frames, the first ones consumed, are drawn as <name>_<tap>.svg, "
            "<name> the analyzer's name in the pipeline (0: none)")
      .min(0);
  return s;
}

ArchesAnalyzer::ArchesAnalyzer(const PluginContext& ctx)
    : log_(ctx.log),
      files_(ctx.output_files()),
      provenance_(ctx.provenance),
      tolerance_(ctx.params.real(kContactToleranceName)),
      span_bin_(ctx.params.real("span_bin")),
      svg_frames_(static_cast<long>(ctx.params.integer("svg_frames"))),
      span_all_(span_bin_, ctx.param("span_bin")),
      per_frame_(ctx.stream_table(
          "per_frame", Table(kPerFrameColumns, "per-frame values of the arch analysis"))) {
  std::set<std::int64_t> seen;
  for (std::int64_t s : ctx.params.integers("span_sizes")) {
    if (!seen.insert(s).second) {
      throw InputError(ctx.param("span_sizes") + ": expected distinct arch sizes, got " +
                       std::to_string(s) + " twice");
    }
    span_by_size_.emplace_back(static_cast<long>(s),
                               SpanHistogram(span_bin_, ctx.param("span_bin")));
  }
}

void ArchesAnalyzer::add_size_distribution(const std::vector<Eigen::Index>& n, double disks) {
  // An arch size first seen now was absent (n = 0) from every earlier frame.
  while (n_per_particle_.size() < n.size()) {
    RunningMean m;
    m.add(0.0, measured_frames_ - 1);
    n_per_particle_.push_back(m);
  }
  for (std::size_t s = 1; s < n_per_particle_.size(); ++s) {
    n_per_particle_[s].add(s < n.size() ? static_cast<double>(n[s]) / disks : 0.0);
  }
}

void ArchesAnalyzer::consume(const Frame& frame, FrameCache& cache) {
  const std::string where = frame_name(frames_, frame);
  ++frames_;
  check_supports(frame, where);
  check_supports_touch(frame, where);
  check_support_sides(frame, where);
  const Eigen::Index n = frame.size();
  arch_of_.resize(0);
  if (n == 0) {
    log_.warn(where + ": no disks; skipped");
    return;
  }
  ++measured_frames_;
  if (coarse_.pending()) {
    const std::string why = coarse_for_contacts(frame, tolerance_);
    if (!why.empty()) coarse_.warn(log_, where + ": " + why);
  }
  const double disks = static_cast<double>(n);

  const std::vector<Arch> arches = find_arches(frame, where);
  arch_of_ = arch_of_each_disk(n, arches);
  const ArchStatistics st = arch_statistics(n, arches);
  const Supports supports = Supports::of(frame);
  const SupportCount sc = count_supports(supports);
  const ContactCensus cc =
      census_contacts(supports, contacts_by_distance(frame, cache, tolerance_));

  const double arches_per_particle = static_cast<double>(st.arches()) / disks;
  const double p1 = static_cast<double>(st.p1) / disks, p2 = static_cast<double>(st.p2) / disks;
  const double z_eq4 = st.z_eq4(), z_direct = sc.z_direct();
  arches_per_particle_.add(arches_per_particle);
  p1_.add(p1);
  p2_.add(p2);
  z_eq4_.add(z_eq4);
  z_direct_.add(z_direct);
  z_difference_.add(z_eq4 - z_direct);
  const double base_fraction = static_cast<double>(sc.base_disks) / disks;
  const double missing = static_cast<double>(sc.missing_supports()) / disks;
  base_fraction_.add(base_fraction);
  missing_supports_.add(missing);
  const double non_supporting =
      cc.contacts > 0 ? static_cast<double>(cc.non_supporting()) / static_cast<double>(cc.contacts)
                      : std::nan("");
  if (cc.contacts > 0) {
    non_supporting_.add(non_supporting);
  } else if (no_contacts_.pending()) {
    no_contacts_.warn(log_, where +
                                ": no disk touches another or a wall: its "
                                "non_supporting_contact_fraction is undefined (NaN in per_frame)");
  }
  if (sc.contacts() > 0) {
    detached_.add(static_cast<double>(sc.contacts() - cc.supporting) /
                  static_cast<double>(sc.contacts()));
  }
  add_size_distribution(st.n, disks);

  const double diameter = 2.0 * frame.radius().mean();
  for (const Arch& a : arches) {
    const double x = a.span / diameter;
    span_all_.add(x);
    for (auto& [size, histogram] : span_by_size_) {
      if (static_cast<long>(a.disks.size()) == size) histogram.add(x);
    }
  }

  by_ramp_.add(frame, {z_eq4, z_direct, arches_per_particle});
  // A frame of a source without taps or cycles has none: NaN, not a tap -1.
  auto observable = [&](const char* name) {
    const auto value = frame.integer_observable(name);
    return value ? static_cast<double>(*value) : std::nan("");
  };
  const std::int64_t tap = frame.integer_observable("tap").value_or(-1);
  per_frame_.add_row({static_cast<double>(frames_ - 1), observable("tap"), observable("cycle"),
                      arches_per_particle, p1, p2, z_eq4, z_direct, base_fraction, missing,
                      non_supporting});

  if (drawn_ < svg_frames_ && files_.enabled()) {
    const std::string stem = tap >= 0 ? std::to_string(tap) : "frame" + std::to_string(frames_ - 1);
    write_arches_svg(
        files_.path("_" + stem + ".svg"), frame, arches,
        where + ": " + std::to_string(n) + " disks, " + std::to_string(st.arches()) + " arches",
        provenance_);
    ++drawn_;
  }
}

// A mean over no frame, or a distribution of no arch, is NaN in the results: said so.
void ArchesAnalyzer::warn_undefined() const {
  if (measured_frames_ == 0) return;
  if (non_supporting_.count() == 0) {
    log_.warn(
        "arches: no frame had a contact: non_supporting_contact_fraction is undefined "
        "(NaN)");
  }
  if (detached_.count() == 0) {
    log_.warn(
        "arches: no frame had a supporting contact: detached_support_fraction is "
        "undefined (NaN)");
  }
  if (span_all_.total() == 0)
    log_.warn("arches: no arch in any frame: the span distribution span_all is undefined (NaN)");
}

void ArchesAnalyzer::finish(Results& results) {
  warn_undefined();
  results.add_scalar("frames", static_cast<double>(measured_frames_), std::nan(""), "",
                     "frames analysed (frames without disks are skipped)");
  results.add_mean("arches_per_particle", arches_per_particle_, "",
                   "arches of two or more disks per disk");
  results.add_mean("p1_over_N", p1_, "", "end particles of arches per disk, Eq. (1)");
  results.add_mean("p2_over_N", p2_, "", "centre particles of arches per disk, Eq. (2)");
  results.add_mean(
      "z_support_eq4", z_eq4_, "",
      "<z>_support = 2 [1 + sum_s n(s) / N], Eq. (4): counts base disks as two-supported");
  results.add_mean("z_support_direct", z_direct_, "",
                   "<z>_support = 2 (distinct supporting contacts) / N, the base counted once");
  results.add_mean("z_support_eq4_minus_direct", z_difference_, "",
                   "Eq. (4) minus the direct count: 2 sum_i (2 - k_i) / N, = 2 base_fraction when "
                   "every disk off the base has two supports");
  results.add_mean("base_fraction", base_fraction_, "", "disks resting on the base per disk");
  results.add_mean("missing_supports_per_particle", missing_supports_, "",
                   "sum_i (2 - k_i) / N, k_i the distinct supporting partners of disk i");
  results.add_mean("non_supporting_contact_fraction", non_supporting_, "",
                   "geometric contacts (disk-disk and disk-wall) that support neither disk");
  results.add_mean("detached_support_fraction", detached_, "",
                   "supporting contacts named by the labels whose partners do not touch (0 for a "
                   "consistent source)");

  Table sizes({"s", "n_s_per_N", "err"},
              "arch size distribution n(s)/N per frame, averaged over frames; s = 1 counts "
              "disks in no arch");
  sizes.units.assign(3, "");
  for (std::size_t s = 1; s < n_per_particle_.size(); ++s) {
    sizes.add_row(
        {static_cast<double>(s), n_per_particle_[s].mean(), n_per_particle_[s].standard_error()});
  }
  results.add_table("arch_size_distribution", std::move(sizes));
  results.add_plot("arch_size_distribution_plot", {.table = "arch_size_distribution",
                                                   .x = "s",
                                                   .y = {"n_s_per_N"},
                                                   .xlabel = "arch size s",
                                                   .ylabel = "n(s) / N",
                                                   .title = "arch size distribution",
                                                   .logy = true});

  const std::string xlabel = "horizontal span x (mean disk diameters)";
  for (const auto& [size, histogram] : span_by_size_) {
    if (histogram.total() == 0 && measured_frames_ > 0) {
      log_.warn("arches: no arch of size " + std::to_string(size) +
                " in any frame: its span distribution span_s" + std::to_string(size) +
                " is undefined (NaN)");
    }
    results.add_histogram(
        "span_s" + std::to_string(size),
        histogram.density(xlabel, "span distribution n_s(x) of arches of " + std::to_string(size) +
                                      " disks (" + std::to_string(histogram.total()) + " arches)"));
  }
  results.add_histogram(
      "span_all", span_all_.density(xlabel, "span distribution n(x) over all arches (" +
                                                std::to_string(span_all_.total()) + " arches)"));
  results.add_table("per_frame", per_frame_.table());
  if (!by_ramp_.empty()) {
    results.add_table("by_ramp", by_ramp_.table("per ramp branch (0 first increase, 1 decreasing, "
                                                "2 increasing) and time (annealed tapping: the "
                                                "amplitude A), pooled over cycles"));
  }
}

}  // namespace granpipe::arches
