#pragma once
// An H5MD element as found in any H5MD 1.x file: either a time-dependent group
// (step, optional time, value) with explicit or fixed ("step increment + offset") clocks,
// or a time-independent dataset that holds for every frame.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "h5_dataset.hpp"

namespace granpipe::h5 {

class Element {
 public:
  // The element at `path`, or nothing when there is none.
  static std::optional<Element> open(hid_t file, const std::string& path);

  const std::string& path() const { return data_path_; }  // the dataset holding the data
  bool timed() const { return timed_; }
  // Samples stored (time-dependent elements; 1 otherwise).
  hsize_t samples() const { return timed_ ? samples_ : 1; }
  // Shape of one sample (the value shape without its time axis).
  Shape item() const;
  const std::vector<std::int64_t>& steps() const { return steps_; }
  const std::vector<double>& times() const { return times_; }  // empty: no time stored
  // H5MD gives every sample one step (and one time, when stored): only a writer stopped
  // mid-sample leaves a clock of another length than value. That clock's dataset and rows.
  struct MismatchedClock {
    std::string path;
    hsize_t rows;
  };
  std::optional<MismatchedClock> mismatched_clock() const;
  hsize_t value_rows() const { return timed_ ? shape_[0] : 1; }

  // Frame k is sample k (elements sampled with the frames, e.g. hard-linked clocks).
  void map_identity();
  // Frame k is the sample with step frame_steps[k]; false when some frame has no sample.
  bool map_by_step(const std::vector<std::int64_t>& frame_steps);

  // The dataset holding the values, and the row of frame k in it (time-dependent
  // elements; a time-independent one holds every frame whole).
  hid_t dataset() const { return value_.id(); }
  hsize_t row(long frame) const;

  // Reads frame k (all of a time-independent element) as doubles or 64-bit integers.
  void read(long frame, double* out) const;
  std::vector<std::int64_t> read_integers(long frame) const;

 private:
  std::string data_path_;
  Object value_;
  Shape shape_;
  bool timed_ = false;
  hsize_t samples_ = 0;
  std::vector<std::int64_t> steps_;
  std::vector<double> times_;
  hsize_t step_rows_ = 0, time_rows_ = 0;  // rows of explicit clocks; fixed ones: value's
  std::vector<hsize_t> rows_;              // sample of each frame; empty: frame k is sample k
};

}  // namespace granpipe::h5
