#include "report_spec.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/errors.hpp"

namespace granpipe {
namespace {

using nlohmann::json;

[[noreturn]] void refuse(const JsonLocation& at, const std::string& expected, const json& found) {
  throw InputError(at.str() + ": expected " + expected + ", got " + json_brief(found));
}

std::string producer_list(const std::set<std::string>& producers) {
  std::string list;
  for (const auto& p : producers) list += (list.empty() ? "" : ", ") + p;
  return list;
}

// "producer<separator>name" with a producer of this pipeline.
void check_named(const json& v, char separator, const std::set<std::string>& producers,
                 const JsonLocation& at) {
  const std::string form = std::string("\"PRODUCER") + separator + "NAME\" with PRODUCER one of " +
                           producer_list(producers);
  if (!v.is_string()) refuse(at, form, v);
  const std::string s = v.get<std::string>();
  const auto cut = s.find(separator);
  if (cut == std::string::npos || cut + 1 == s.size() || !producers.count(s.substr(0, cut)))
    refuse(at, form, v);
}

// A list of finite numbers; `length` 0 takes any length of at least one.
std::size_t check_numbers(const json& v, std::size_t length, bool non_negative,
                          const JsonLocation& at) {
  const std::string what = std::string("a list of ") +
                           (length ? std::to_string(length) + " " : "") +
                           (non_negative ? "finite numbers >= 0" : "finite numbers");
  if (!v.is_array() || v.empty() || (length && v.size() != length)) refuse(at, what, v);
  for (std::size_t k = 0; k < v.size(); ++k) {
    const bool ok = v[k].is_number() && std::isfinite(v[k].get<double>()) &&
                    !(non_negative && v[k].get<double>() < 0);
    if (!ok) refuse(at.index(k), non_negative ? "a finite number >= 0" : "a finite number", v[k]);
  }
  return v.size();
}

// `sweep_plots` are "sweep/NAME" for each plot of report.sweep_plots.
void check_paper_values(const json& entry, const std::set<std::string>& producers,
                        const std::set<std::string>& sweep_plots, const JsonLocation& at) {
  check_keys(entry, {"plot", "label", "x", "y", "y_err"}, at);
  for (const char* key : {"plot", "label", "x", "y"})
    if (!entry.contains(key)) refuse(at.child(key), "a value", json());
  const bool on_sweep_plot = entry["plot"].is_string() && sweep_plots.count(entry["plot"]);
  if (!on_sweep_plot && entry["plot"].is_string() &&
      entry["plot"].get<std::string>().rfind("sweep/", 0) == 0)
    refuse(at.child("plot"), "a plot named in report.sweep_plots", entry["plot"]);
  if (!on_sweep_plot) check_named(entry["plot"], '/', producers, at.child("plot"));
  if (!entry["label"].is_string() || entry["label"].get<std::string>().empty())
    refuse(at.child("label"), "a label (\"paper, Fig. 4\")", entry["label"]);
  const std::size_t n = check_numbers(entry["x"], 0, false, at.child("x"));
  check_numbers(entry["y"], n, false, at.child("y"));
  if (entry.contains("y_err")) check_numbers(entry["y_err"], n, true, at.child("y_err"));
}

void check_swept(const json& v, const std::vector<std::string>& sweep_paths,
                 const JsonLocation& at) {
  if (sweep_paths.empty()) refuse(at, "a swept parameter, and so a sweep", v);
  const bool swept =
      v.is_string() && std::count(sweep_paths.begin(), sweep_paths.end(), v.get<std::string>());
  if (!swept) {
    std::string list;
    for (const auto& p : sweep_paths) list += (list.empty() ? "" : ", ") + p;
    refuse(at, "a swept parameter (" + list + ")", v);
  }
}

void check_label(const json& spec, const char* key, const JsonLocation& at) {
  if (spec.contains(key) && !spec[key].is_string()) refuse(at.child(key), "a string", spec[key]);
}

void check_flag(const json& spec, const char* key, const JsonLocation& at) {
  if (spec.contains(key) && !spec[key].is_boolean())
    refuse(at.child(key), "true or false", spec[key]);
}

// Returns "sweep/NAME", the plot's name for paper values.
std::string check_sweep_plot(const json& spec, const std::set<std::string>& producers,
                             const std::vector<std::string>& sweep_paths, const JsonLocation& at) {
  check_keys(spec, {"name", "x", "y", "xlabel", "ylabel", "title", "logx", "logy"}, at);
  for (const char* key : {"name", "x", "y"})
    if (!spec.contains(key)) refuse(at.child(key), "a value", json());
  if (!spec["name"].is_string() || spec["name"].get<std::string>().empty())
    refuse(at.child("name"), "a name for the plot", spec["name"]);
  check_swept(spec["x"], sweep_paths, at.child("x"));
  const json& y = spec["y"];
  if (!y.is_array() || y.empty())
    refuse(at.child("y"), "a list of result columns (\"packing.phi\")", y);
  for (std::size_t k = 0; k < y.size(); ++k)
    check_named(y[k], '.', producers, at.child("y").index(k));
  for (const char* key : {"xlabel", "ylabel", "title"}) check_label(spec, key, at);
  for (const char* key : {"logx", "logy"}) check_flag(spec, key, at);
  return "sweep/" + spec["name"].get<std::string>();
}

void check_speed_vs_error(const json& spec, const std::set<std::string>& producers,
                          const std::vector<std::string>& sweep_paths, const JsonLocation& at) {
  check_keys(spec, {"knob", "time", "quantities", "pool"}, at);
  for (const char* key : {"knob", "time", "quantities"})
    if (!spec.contains(key)) refuse(at.child(key), "a value", json());
  check_swept(spec["knob"], sweep_paths, at.child("knob"));
  if (spec.contains("pool")) {
    check_swept(spec["pool"], sweep_paths, at.child("pool"));
    if (spec["pool"] == spec["knob"])
      refuse(at.child("pool"), "a parameter other than the knob", spec["pool"]);
  }
  check_named(spec["time"], '.', producers, at.child("time"));
  const json& quantities = spec["quantities"];
  if (!quantities.is_array() || quantities.empty())
    refuse(at.child("quantities"), "a list of result columns (\"packing.phi\")", quantities);
  for (std::size_t k = 0; k < quantities.size(); ++k)
    check_named(quantities[k], '.', producers, at.child("quantities").index(k));
}

}  // namespace

void check_report_spec(const json& root, const JsonLocation& top,
                       const std::set<std::string>& producers,
                       const std::vector<std::string>& sweep_paths) {
  if (!root.contains("report")) return;
  const JsonLocation at = top.child("report");
  const json& report = root["report"];
  check_keys(report, {"paper", "sweep_plots", "speed_vs_error"}, at);
  std::set<std::string> sweep_plots;
  if (report.contains("sweep_plots")) {
    const json& plots = report["sweep_plots"];
    if (!plots.is_array()) refuse(at.child("sweep_plots"), "a list of sweep plots", plots);
    for (std::size_t k = 0; k < plots.size(); ++k) {
      const JsonLocation plot_at = at.child("sweep_plots").index(k);
      if (!sweep_plots.insert(check_sweep_plot(plots[k], producers, sweep_paths, plot_at)).second)
        refuse(plot_at.child("name"), "a name no other sweep plot has", plots[k]["name"]);
    }
  }
  if (report.contains("paper")) {
    const json& paper = report["paper"];
    if (!paper.is_array()) refuse(at.child("paper"), "a list of paper values", paper);
    for (std::size_t k = 0; k < paper.size(); ++k)
      check_paper_values(paper[k], producers, sweep_plots, at.child("paper").index(k));
  }
  if (report.contains("speed_vs_error"))
    check_speed_vs_error(report["speed_vs_error"], producers, sweep_paths,
                         at.child("speed_vs_error"));
}

}  // namespace granpipe
