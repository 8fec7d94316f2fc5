#include "granpipe/ramp_means.hpp"

#include <cmath>
#include <optional>

#include "granpipe/errors.hpp"

namespace granpipe {

RampBranch ramp_branch(std::int64_t cycle) {
  if (cycle == 0) return RampBranch::FirstIncrease;
  return cycle % 2 == 1 ? RampBranch::Decreasing : RampBranch::Increasing;
}

void RampMeans::add(const Frame& frame, const std::vector<double>& values) {
  const std::optional<std::int64_t> cycle = frame.integer_observable(cycle_);
  const std::optional<double> control = frame.real_observable(control_);
  if (!cycle || *cycle < 0 || !control) return;
  if (values.size() != names_.size())
    throw InternalError("RampMeans: one value per quantity expected");
  Means& means = means_[{ramp_branch(*cycle), *control}];
  means.of.resize(names_.size());
  ++means.frames;
  for (std::size_t q = 0; q < values.size(); ++q)
    if (!std::isnan(values[q])) means.of[q].add(values[q]);
}

Table RampMeans::table(const std::string& doc) const {
  std::vector<std::string> columns{"branch", control_, "frames"};
  for (const auto& n : names_) {
    columns.push_back(n);
    columns.push_back(n + "_err");
  }
  Table t(columns, doc);
  for (const auto& [key, means] : means_) {
    std::vector<double> row{static_cast<double>(key.first), key.second,
                            static_cast<double>(means.frames)};
    for (const RunningMean& m : means.of) {
      row.push_back(m.count() > 0 ? m.mean() : std::nan(""));
      row.push_back(m.standard_error());
    }
    t.add_row(row);
  }
  return t;
}

}  // namespace granpipe
