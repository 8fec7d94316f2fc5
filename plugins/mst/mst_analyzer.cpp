#include "mst_analyzer.hpp"

#include <cmath>
#include <string>

#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe::mst {

namespace {

const Property kMstPass{"mst_pass",
                        Scope::Contact,
                        ValueType::Integer,
                        1,
                        "",
                        "first MST pass that selected this contact (0: none, or not counted)"};
const Property kTcp{
    "tcp",
    Scope::Particle,
    ValueType::Integer,
    1,
    "",
    "tree of contacting particles after the last MST pass (0 the largest; -1 none)"};

const std::vector<std::string> kTableColumns = {"pass",
                                                "tcp_largest_particles",
                                                "tcp_largest_edges",
                                                "tcp_others",
                                                "tcp_other_edges",
                                                "network_largest_particles",
                                                "network_largest_edges",
                                                "network_others",
                                                "network_other_edges",
                                                "contacts",
                                                "contacts_selected",
                                                "recovered_fraction"};

std::vector<double> table_row(const TcpReport& r, const PassRow& p) {
  auto d = [](std::int64_t v) { return static_cast<double>(v); };
  return {static_cast<double>(p.pass),
          d(p.tcp.largest_particles),
          d(p.tcp.largest_edges),
          d(p.tcp.others),
          d(p.tcp.other_edges),
          d(r.network.largest_particles),
          d(r.network.largest_edges),
          d(r.network.others),
          d(r.network.other_edges),
          d(r.contacts),
          d(p.selected),
          r.recovered(p)};
}

}  // namespace

Schema schema() {
  Schema s;
  s.choice<Candidates>("candidates", Candidates::Cutoff,
                       "the pairs the MST may join: \"cutoff\" (|r_ij| < cutoff (R_i + R_j), "
                       "cell list, periodic sides too) or \"delaunay\" (the Delaunay "
                       "triangulation's edges, which contain the Euclidean MST; no periodic "
                       "sides); docs/mst.md says when either is exact");
  s.real("cutoff", 0.0,
         "candidates \"cutoff\": the largest centre distance of a candidate pair, in units of "
         "R_i + R_j; 0: per frame, the smallest that makes every contact's selection exact "
         "(elongation x longest contact / (2 R_min)), within [1, 3]")
      .min(0.0)
      .only_where("candidates cutoff", [](const Params& p) {
        return p.choice<Candidates>("candidates") == Candidates::Cutoff;
      });
  s.real("elongation", 1.2,
         "factor lengthening, once, every edge selected by an earlier pass before the next "
         "pass")
      .min(1.0);
  s.integer("passes", 5, "MST passes").range(1, 1000);
  s.boolean("zero_force_contacts", false,
            "rows of the frame's contact table with a zero normal force count as contacts "
            "(by default only non-zero forces do: the force network)");
  declare_contact_tolerance(s);
  return s;
}

MstAnalyzer::MstAnalyzer(const PluginContext& ctx)
    : log_(ctx.log),
      options_{.candidates = ctx.params.choice<Candidates>("candidates"),
               .cutoff = ctx.params.real("cutoff"),
               .elongation = ctx.params.real("elongation"),
               .passes = static_cast<int>(ctx.params.integer("passes")),
               .contacts = {.zero_force_contacts = ctx.params.boolean("zero_force_contacts"),
                            .tolerance = ctx.params.real(kContactToleranceName)}},
      per_frame_(ctx.stream_table("per_frame", [] {
        std::vector<std::string> columns = {"frame", "time"};
        columns.insert(columns.end(), kTableColumns.begin(), kTableColumns.end());
        columns.push_back("unproven_contacts");
        return Table(columns,
                     "Table II per frame and pass: the largest TCP and the other TCPs (2 "
                     "particles or more), the same of the contact network, and the share of "
                     "contacts the passes so far selected; unproven_contacts: contacts "
                     "whose selection the candidate graph is not shown to reproduce");
      }())) {}

std::vector<Property> MstAnalyzer::publishes() const { return {kMstPass, kTcp}; }

void MstAnalyzer::publish(PropertyTable& columns) {
  if (columns.scope() == Scope::Contact) {
    columns.get<IndexArray>(kMstPass.name) = mst_pass_;
  } else {
    columns.get<IndexArray>(kTcp.name) = tcp_;
  }
}

void MstAnalyzer::consume(const Frame& frame, FrameCache& cache) {
  const std::string where = "frame " + std::to_string(frames_);
  if (!frame.contacts && coarse_.pending()) {
    const std::string why = coarse_for_contacts(frame, options_.contacts.tolerance);
    if (!why.empty()) coarse_.warn(log_, "mst: " + where + ": " + why);
  }
  const TcpReport r = tcp_report(frame, cache, options_, where);
  if (r.unproven > 0 && !warned_inexact_) {
    warned_inexact_ = true;
    log_.warn("mst: " + where + ": " + std::to_string(r.unproven) +
              " contacts, lengthened, are not shorter than " + format_number(r.complete_below) +
              ", below which the candidate graph holds every pair: their selection may differ "
              "from the MST of all pairs (docs/mst.md; column unproven_contacts)");
  }
  if (r.contacts == 0) {
    no_contacts_.warn(log_, "mst: " + where +
                                ": no contacts: its recovered_fraction is undefined (nan in "
                                "per_frame, not 0; docs/mst.md)");
  }
  for (const PassRow& p : r.passes) {
    std::vector<double> row = {static_cast<double>(frames_), frame.time};
    const std::vector<double> counts = table_row(r, p);
    row.insert(row.end(), counts.begin(), counts.end());
    row.push_back(static_cast<double>(r.unproven));
    per_frame_.add_row(row);
  }
  if (chosen_.offer(frames_, r.pairs.loaded)) keep_table_ii(frame, r);

  frames_with_table_ += frame.contacts ? 1 : 0;
  tcp_ = r.tcp;
  mst_pass_.resize(frame.contacts ? frame.contacts->rows() : 0);
  for (Eigen::Index k = 0; k < mst_pass_.size(); ++k) {
    const std::int64_t pair = r.pairs.pair_of_row[static_cast<std::size_t>(k)];
    mst_pass_[k] = pair < 0 ? 0 : r.first_pass[static_cast<std::size_t>(pair)];
  }
  ++frames_;
}

void MstAnalyzer::keep_table_ii(const Frame& frame, const TcpReport& report) {
  chosen_time_ = frame.time;
  table_ii_ = Table(kTableColumns,
                    "this run's Table II (as Sun, Battaglia & Subramaniam 2006 lay it out) for "
                    "the frame with the most particle-particle contacts of non-zero normal "
                    "force (frame table_ii_frame)");
  for (const PassRow& p : report.passes) table_ii_.add_row(table_row(report, p));
}

// Which contacts a frame has depends on the data (a contact table, or distances), so a
// parameter of the other way is said to have done nothing rather than refused.
void MstAnalyzer::warn_idle_contact_rule() const {
  if (options_.contacts.zero_force_contacts && frames_with_table_ == 0) {
    log_.warn(
        "mst: zero_force_contacts had no effect: no frame carried a contact table, so "
        "contacts were found by distance (contact_tolerance)");
  }
  if (options_.contacts.tolerance != kDefaultContactTolerance && frames_with_table_ == frames_) {
    log_.warn(
        "mst: contact_tolerance had no effect: every frame carried a contact table, "
        "whose contacts were used");
  }
}

void MstAnalyzer::finish(Results& results) {
  if (frames_ > 0) warn_idle_contact_rule();
  results.add_table("per_frame", per_frame_.table());
  results.add_scalar("frames", static_cast<double>(frames_), std::nan(""), "", "frames analysed");
  if (chosen_.frame() < 0) return;
  results.add_table("table_ii", table_ii_);
  results.add_scalar("table_ii_frame", static_cast<double>(chosen_.frame()), std::nan(""), "",
                     "frame (counted from 0) that table_ii describes");
  results.add_scalar("table_ii_time", chosen_time_, std::nan(""), "time",
                     "time of the frame that table_ii describes");
  results.add_plot("recovered", {.table = "table_ii",
                                 .x = "pass",
                                 .y = {"recovered_fraction"},
                                 .xlabel = "MST passes",
                                 .ylabel = "contacts recovered",
                                 .title = "share of contacts selected by the multipass MST"});
}

}  // namespace granpipe::mst
