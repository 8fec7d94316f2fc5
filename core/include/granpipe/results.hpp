#pragma once
// What analyzers (and sources) report. Results are plain values; the result store
// writes them to results.h5 and CSV. Names are unique within one Results.
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace granpipe {

struct Scalar {
  double value = 0.0;
  double uncertainty = std::numeric_limits<double>::quiet_NaN();  // NaN: none
  std::string unit;
  std::string doc;
};

// Columns of equal length: a series (x and one or more y), or any table.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::string> units;         // one per column, "" dimensionless
  std::vector<std::vector<double>> data;  // data[column][row]
  std::string doc;

  Table() = default;
  Table(std::vector<std::string> cols, std::string doc_line = "");
  // With the columns' units, one per column.
  Table(std::vector<std::string> cols, std::string doc_line, std::vector<std::string> col_units);
  void add_row(const std::vector<double>& row);
  std::size_t rows() const { return data.empty() ? 0 : data.front().size(); }
  const std::vector<double>& column(const std::string& name) const;
};

struct Histogram {
  std::vector<double> edges;   // bins + 1
  std::vector<double> values;  // bins: counts, or a density when `density`
  std::vector<double> errors;  // bins, empty when unknown
  bool density = false;
  std::string xlabel;
  std::string doc;
};

struct Fit {
  std::string model;  // the formula, e.g. "phi(t) = phi_inf - dphi / (1 + B ln(1 + t/tau))"
  std::vector<std::string> names;
  std::vector<double> values, errors;
  Eigen::MatrixXd covariance;
  double chi2 = std::numeric_limits<double>::quiet_NaN();
  int dof = 0;
};

// A plot declaration: which table's columns to draw, how to label the axes.
struct Plot {
  std::string table;
  std::string x;
  std::vector<std::string> y;
  std::string xlabel, ylabel, title;
  bool logx = false, logy = false;
};

// Where the rows of streamed tables go while a run goes: the run's results.h5, flushed
// row by row, so that a run killed after hours keeps every row added before the kill.
class ResultStreams {
 public:
  virtual ~ResultStreams() = default;
  // Declares table `name` of producer `group` (before the run starts); returns its id.
  virtual std::size_t declare(const std::string& group, const std::string& name,
                              const Table& empty) = 0;
  virtual void append(std::size_t id, const std::vector<double>& row) = 0;
};

// A table whose rows reach results.h5 as they are added (a per-frame time series). Made
// by PluginContext::stream_table; it also keeps its rows, for the table a plugin reports
// in finish() as usual.
class StreamedTable {
 public:
  StreamedTable() = default;
  StreamedTable(Table empty, ResultStreams* streams, std::size_t id)
      : table_(std::move(empty)), streams_(streams), id_(id) {}
  void add_row(const std::vector<double>& row);
  const Table& table() const { return table_; }

 private:
  Table table_;
  ResultStreams* streams_ = nullptr;  // none when a pipeline is only checked
  std::size_t id_ = 0;
};

class RunningMean;

class Results {
 public:
  void add_scalar(const std::string& name, double value, double uncertainty = std::nan(""),
                  const std::string& unit = "", const std::string& doc = "");
  // A mean over frames with its standard error; NaN when no frame contributed.
  void add_mean(const std::string& name, const RunningMean& mean, const std::string& unit = "",
                const std::string& doc = "");
  void add_table(const std::string& name, Table table);
  void add_histogram(const std::string& name, Histogram h);
  void add_fit(const std::string& name, Fit fit);
  void add_plot(const std::string& name, Plot plot);

  const std::map<std::string, Scalar>& scalars() const { return scalars_; }
  const std::map<std::string, Table>& tables() const { return tables_; }
  const std::map<std::string, Histogram>& histograms() const { return histograms_; }
  const std::map<std::string, Fit>& fits() const { return fits_; }
  const std::map<std::string, Plot>& plots() const { return plots_; }
  const Scalar& scalar(const std::string& name) const;
  bool empty() const;

 private:
  void claim(const std::string& name);
  std::map<std::string, Scalar> scalars_;
  std::map<std::string, Table> tables_;
  std::map<std::string, Histogram> histograms_;
  std::map<std::string, Fit> fits_;
  std::map<std::string, Plot> plots_;
};

// Mean and standard error of per-frame values, accumulated without storing them
// (Welford). Frames of a Markov chain are correlated: the error is the naive one
// unless the caller blocks the data.
class RunningMean {
 public:
  void add(double x);
  // Adds x `times` times at once (Chan et al.'s pairwise update): e.g. the zeros of the
  // earlier frames for a histogram bin seen for the first time.
  void add(double x, long times);
  long count() const { return n_; }
  double mean() const { return mean_; }
  double variance() const { return n_ > 1 ? m2_ / static_cast<double>(n_ - 1) : 0.0; }
  double standard_error() const;
  void reset() { *this = RunningMean(); }

 private:
  long n_ = 0;
  double mean_ = 0.0, m2_ = 0.0;
};

}  // namespace granpipe
