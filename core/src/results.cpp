#include "granpipe/results.hpp"

#include <cmath>

#include "granpipe/errors.hpp"

namespace granpipe {

Table::Table(std::vector<std::string> cols, std::string doc_line)
    : columns(std::move(cols)),
      units(columns.size()),
      data(columns.size()),
      doc(std::move(doc_line)) {}

Table::Table(std::vector<std::string> cols, std::string doc_line,
             std::vector<std::string> col_units)
    : Table(std::move(cols), std::move(doc_line)) {
  if (col_units.size() != columns.size()) {
    throw InternalError("table of " + std::to_string(columns.size()) + " columns given " +
                        std::to_string(col_units.size()) + " units");
  }
  units = std::move(col_units);
}

void Table::add_row(const std::vector<double>& row) {
  if (row.size() != columns.size()) {
    throw InternalError("table row has " + std::to_string(row.size()) + " values for " +
                        std::to_string(columns.size()) + " columns");
  }
  for (std::size_t c = 0; c < row.size(); ++c) data[c].push_back(row[c]);
}

const std::vector<double>& Table::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return data[c];
  throw InternalError("table has no column '" + name + "'");
}

void Results::claim(const std::string& name) {
  if (scalars_.count(name) || tables_.count(name) || histograms_.count(name) || fits_.count(name) ||
      plots_.count(name)) {
    throw InternalError("result '" + name + "' reported twice");
  }
}

void Results::add_scalar(const std::string& name, double value, double uncertainty,
                         const std::string& unit, const std::string& doc) {
  claim(name);
  scalars_[name] = {value, uncertainty, unit, doc};
}

void Results::add_mean(const std::string& name, const RunningMean& mean, const std::string& unit,
                       const std::string& doc) {
  add_scalar(name, mean.count() > 0 ? mean.mean() : std::nan(""), mean.standard_error(), unit, doc);
}

void Results::add_table(const std::string& name, Table table) {
  claim(name);
  for (const auto& col : table.data) {
    if (col.size() != table.rows()) throw InternalError("table '" + name + "' is ragged");
  }
  table.units.resize(table.columns.size());
  tables_[name] = std::move(table);
}

void Results::add_histogram(const std::string& name, Histogram h) {
  claim(name);
  if (h.edges.size() != h.values.size() + 1 ||
      (!h.errors.empty() && h.errors.size() != h.values.size())) {
    throw InternalError("histogram '" + name + "' needs one more edge than bins");
  }
  histograms_[name] = std::move(h);
}

void Results::add_fit(const std::string& name, Fit fit) {
  claim(name);
  fits_[name] = std::move(fit);
}

void Results::add_plot(const std::string& name, Plot plot) {
  if (plots_.count(name)) throw InternalError("plot '" + name + "' declared twice");
  plots_[name] = std::move(plot);
}

const Scalar& Results::scalar(const std::string& name) const {
  auto it = scalars_.find(name);
  if (it == scalars_.end()) throw InternalError("no scalar result '" + name + "'");
  return it->second;
}

bool Results::empty() const {
  return scalars_.empty() && tables_.empty() && histograms_.empty() && fits_.empty();
}

void RunningMean::add(double x) {
  ++n_;
  const double d = x - mean_;
  mean_ += d / static_cast<double>(n_);
  m2_ += d * (x - mean_);
}

void RunningMean::add(double x, long times) {
  if (times <= 0) return;
  const double nb = static_cast<double>(times), na = static_cast<double>(n_);
  const double d = x - mean_;
  n_ += times;
  mean_ += d * nb / static_cast<double>(n_);
  m2_ += d * d * na * nb / static_cast<double>(n_);
}

double RunningMean::standard_error() const {
  return n_ > 1 ? std::sqrt(variance() / static_cast<double>(n_)) : std::nan("");
}

void StreamedTable::add_row(const std::vector<double>& row) {
  table_.add_row(row);
  if (streams_) streams_->append(id_, row);
}

}  // namespace granpipe
