#include "force_network_analyzer.hpp"

#include <cmath>
#include <string>

#include "frame_report.hpp"
#include "granpipe/bin_count.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe::force_network {

namespace {

Settings read_settings(const PluginContext& ctx) {
  const Params& p = ctx.params;
  Settings s{.force = {.min_force = p.real("min_force"), .walls = p.boolean("walls")},
             .bin_width = p.real("bin_width"),
             .f_max = p.real("f_max"),
             .min_fit_samples = p.integer("min_fit_samples"),
             .r_max = p.real("r_max"),
             .r_bins = static_cast<int>(p.integer("r_bins")),
             .by_pass = p.string("by_pass")};
  if (s.f_max / s.bin_width > kMaxPdfBins) {
    throw InputError(
        ctx.param("f_max") + ": expected at most " +
        std::to_string(static_cast<long>(kMaxPdfBins)) +
        " bins of bin_width, got f_max / bin_width = " + format_number(s.f_max / s.bin_width));
  }
  if (s.f_max > 0.0) check_step_fits(s.f_max, s.bin_width, ctx.param("bin_width"), "f_max");
  if (!s.by_pass.empty() && !is_valid_column_name(s.by_pass)) {
    throw InputError(ctx.param("by_pass") +
                     ": expected a contact column name (letters, digits "
                     "and '_', not starting with a digit) or \"\", got \"" +
                     s.by_pass + "\"");
  }
  return s;
}

}  // namespace

Schema schema() {
  Schema s;
  s.real("min_force", 0.0, "a contact joins a force network when |F_n| > min_force")
      .min(0.0)
      .unit("force");
  s.boolean("walls", false,
            "wall contacts with |F_n| > min_force join <F_n>, the PDF and F(r) "
            "(never the networks)");
  s.real("bin_width", 0.2, "bin width of the force PDF, in f = |F_n|/<F_n>").range(1e-6, 1e6);
  s.real("f_max", 0.0,
         "upper end of the PDF's f range (rounded to whole bins); 0: the largest "
         "f of the frame")
      .min(0.0);
  s.integer("min_fit_samples", 100, "fewer contacts than this: the PDF is not fitted")
      .range(1, 1e12);
  s.real("r_max", 10.0, "upper end of the F(r) range").min(0.0, true).unit("length");
  s.integer("r_bins", 50, "bins of F(r)").range(1, 100000);
  s.string("by_pass", "",
           "integer contact column of pass numbers (e.g. mst_pass): also report "
           "the statistics of the contacts of passes 1..k; \"\": off");
  return s;
}

Property ForceNetworkAnalyzer::network_property() {
  return {"network",
          Scope::Particle,
          ValueType::Integer,
          1,
          "",
          "force network label (0 the largest), -1 for a particle in none"};
}

Property ForceNetworkAnalyzer::strong_property() {
  return {"strong",
          Scope::Contact,
          ValueType::Small,
          1,
          "",
          "1 for a force-network contact with |F_n| above the mean, else 0"};
}

ForceNetworkAnalyzer::ForceNetworkAnalyzer(const PluginContext& ctx)
    : log_(ctx.log),
      settings_(read_settings(ctx)),
      per_frame_(ctx.stream_table(
          "per_frame", Table(per_frame_columns(),
                             "force networks, strong sub-network and the Eq. (11) fit of the "
                             "force PDF, per frame"))) {}

FrameContent ForceNetworkAnalyzer::needs() const {
  FrameContent c{.contacts = true,
                 .columns = {*find_standard("normal_force", Scope::Contact),
                             *find_standard("point", Scope::Contact)}};
  if (!settings_.by_pass.empty()) {
    c.columns.push_back({settings_.by_pass, Scope::Contact, ValueType::Integer, 1, "",
                         "pass numbers named by the parameter by_pass"});
  }
  return c;
}

void ForceNetworkAnalyzer::consume(const Frame& frame, FrameCache&) {
  const std::string where = "frame " + std::to_string(frames_);
  if (!settings_.by_pass.empty() && frame.contacts) pass_column(frame, settings_, where);
  const FrameAnalysis a = analyse_frame(frame, settings_, where);
  warn_undefined(a, where);
  per_frame_.add_row(per_frame_row(frames_, frame.time, frame.size(), a));
  if (chosen_.offer(frames_, a.forces.loaded))
    paper_ = paper_frame(frame, a, frames_, settings_, where);
  network_ = a.networks.label;
  strong_ = a.strong.flag;
  ++frames_;
}

// (With walls counted, wall contacts alone left z_largest NaN without a word.)
void ForceNetworkAnalyzer::warn_undefined(const FrameAnalysis& a, const std::string& where) {
  const bool no_samples = a.forces.samples.empty();
  if (!no_samples && a.networks.largest().particles > 0) return;
  undefined_.warn(log_, "force_network: " + where +
                            (no_samples ? ": no contact with |F_n| > min_force: its mean_force, "
                                          "z_largest and force PDF are"
                                        : ": no pair contact with |F_n| > min_force (wall "
                                          "contacts only): no network, and z_largest is") +
                            " undefined (nan in the results, not 0; docs/force_network.md)");
}

std::vector<Property> ForceNetworkAnalyzer::publishes() const {
  return {network_property(), strong_property()};
}

void ForceNetworkAnalyzer::publish(PropertyTable& columns) {
  if (columns.scope() == Scope::Particle) columns.get<IndexArray>("network") = network_;
  if (columns.scope() == Scope::Contact) columns.get<IntArray>("strong") = strong_;
}

void ForceNetworkAnalyzer::finish(Results& results) {
  results.add_table("per_frame", per_frame_.table());
  results.add_plot("networks", {.table = "per_frame",
                                .x = "time",
                                .y = {"largest_particles", "strong_particles_in_largest"},
                                .xlabel = "time",
                                .ylabel = "particles",
                                .title = "largest force network and its strong part"});
  results.add_scalar("frames", static_cast<double>(frames_), std::nan(""), "", "frames measured");
  // With no pass among its contacts the pass tables were left out without a word.
  if (!settings_.by_pass.empty() && paper_.index >= 0 && paper_.passes.empty()) {
    log_.warn("force_network: by_pass: contact column " + settings_.by_pass + " of frame " +
              std::to_string(paper_.index) +
              " (the one analysed in full) names no pass (every row 0): no pass_* results");
  }
  report_paper_frame(paper_, results);
}

}  // namespace granpipe::force_network
