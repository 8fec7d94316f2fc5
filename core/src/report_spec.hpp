#pragma once
// The pipeline's "report" section: what report.html draws beyond the plugins' declared
// plots. Checked with the rest of the pipeline, so that a misspelled plot or column is
// refused before hours of running rather than missing from the page at the end.
//
//   "report": {
//     "sweep_plots": [{"name": "phi", "x": "source.params.A", "y": ["packing.phi"],
//                      "xlabel": "A", "ylabel": "phi", "logx": false, "logy": false}],
//     "paper": [{"plot": "mst/recovered", "label": "paper, Table II",
//                "x": [...], "y": [...], "y_err": [...]}],
//     "speed_vs_error": {"knob": "source.params.eta", "time": "source.seconds",
//                        "quantities": ["stereology.phi_c_last"],
//                        "pool": "source.params.replica"}
//   }
//
// "sweep_plots" draws results against a swept parameter; "paper" overlays a paper's
// values on a plot ("producer/plot" declared by a plugin, or "sweep/NAME"); "speed_vs_error"
// turns a sweep over a resolution knob into run time against the deviation from the
// finest point (scripts/speed_vs_error.py's table, drawn).
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "param_validation.hpp"

namespace granpipe {

// Refuses a malformed "report" section of `root`; `producers` are the names results are
// grouped under ("source" and the analyzers' names), `sweep_paths` the swept parameters.
void check_report_spec(const nlohmann::json& root, const JsonLocation& top,
                       const std::set<std::string>& producers,
                       const std::vector<std::string>& sweep_paths);

}  // namespace granpipe
