#include "h5_element.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "granpipe/format_number.hpp"

namespace granpipe::h5 {
namespace {

// A frame's time orders and labels it: infinity would label every frame after it so. NaN is
// an undefined time (granpipe writes it for a dump without ITEM: TIME or dt, and then
// refused its own file), ordered against nothing (TimeOrder).
void check_finite(const std::vector<double>& times, const std::string& path) {
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isinf(times[k])) continue;
    throw Error(path + ": sample " + std::to_string(k) +
                ": expected a finite time (or NaN, undefined), got " + format_number(times[k]));
  }
}

// Sample i of a fixed clock. A step past the largest integer would wrap round to a
// negative one, without a word.
double fixed_sample(double i, double increment, double offset, const std::string&) {
  return i * increment + offset;
}

std::int64_t fixed_sample(std::int64_t i, std::int64_t increment, std::int64_t offset,
                          const std::string& path) {
  std::int64_t step = 0;
  if (!__builtin_mul_overflow(i, increment, &step) && !__builtin_add_overflow(step, offset, &step))
    return step;
  throw Error(path + ": sample " + std::to_string(i) +
              ": expected a step within 64-bit integers, got " + std::to_string(i) + " x " +
              std::to_string(increment) + " + " + std::to_string(offset));
}

// An H5MD clock (`step` or `time`) for up to `samples` samples: an explicit 1-D dataset
// (possibly shorter than the values), or a scalar increment with an optional `offset`
// attribute (H5MD 1.1 fixed storage), where sample i is at i * increment + offset. `rows`:
// those of an explicit clock, or `samples` for a fixed one (it has as many as asked).
template <class T>
std::vector<T> read_clock(hid_t file, const std::string& path, hsize_t samples, hsize_t& rows) {
  constexpr bool integer = std::is_integral_v<T>;
  const hid_t mem_type = integer ? H5T_NATIVE_INT64 : H5T_NATIVE_DOUBLE;
  Object ds = open_stored_dataset(file, path);
  const Shape shape = shape_of(ds.id(), path);
  std::vector<T> out;
  rows = shape.size() == 1 ? shape[0] : samples;
  if (shape.size() == 1) {
    const hsize_t n = std::min(samples, shape[0]);
    if constexpr (integer) {
      out = read_integer_rows(ds.id(), path, 0, n);
    } else {
      out.resize(n);
      read_rows(ds.id(), path, mem_type, 0, n, out.data());
      check_finite(out, path);
    }
    return out;
  }
  if (!shape.empty()) {
    throw Error(path + ": expected a 1-D array or a scalar increment, got shape " +
                format_shape(shape));
  }
  T increment{};
  read_all(ds.id(), path, mem_type, &increment);
  T offset{};
  if (has_attribute(ds.id(), "offset")) {
    if constexpr (integer) {
      offset = read_integer_attribute(ds.id(), path, "offset").at(0);
    } else {
      offset = read_real_attribute(ds.id(), path, "offset").at(0);
    }
  }
  out.resize(samples);
  for (hsize_t i = 0; i < samples; ++i)
    out[i] = fixed_sample(static_cast<T>(i), increment, offset, path);
  if constexpr (!integer) check_finite(out, path);
  return out;
}

}  // namespace

std::optional<Element> Element::open(hid_t file, const std::string& path) {
  Element e;
  if (is_dataset(file, path)) {
    e.data_path_ = path;
    e.value_ = open_stored_dataset(file, path);
    e.shape_ = shape_of(e.value_.id(), path);
    return e;
  }
  if (!is_group(file, path)) return std::nullopt;
  e.data_path_ = path + "/value";
  if (!is_dataset(file, e.data_path_)) {
    throw Error(e.data_path_ + ": missing (a time-dependent H5MD element holds step and value)");
  }
  e.value_ = open_stored_dataset(file, e.data_path_);
  e.shape_ = shape_of(e.value_.id(), e.data_path_);
  if (e.shape_.empty()) throw Error(e.data_path_ + ": expected an array over time, got a scalar");
  e.timed_ = true;
  if (!is_dataset(file, path + "/step")) {
    throw Error(path + "/step: missing (a time-dependent H5MD element holds step and value)");
  }
  e.steps_ = read_clock<std::int64_t>(file, path + "/step", e.shape_[0], e.step_rows_);
  e.samples_ = e.steps_.size();
  e.time_rows_ = e.shape_[0];
  if (is_dataset(file, path + "/time")) {
    e.times_ = read_clock<double>(file, path + "/time", e.samples_, e.time_rows_);
    e.samples_ = std::min<hsize_t>(e.samples_, e.times_.size());
  }
  return e;
}

std::optional<Element::MismatchedClock> Element::mismatched_clock() const {
  if (!timed_) return std::nullopt;
  const std::string group = data_path_.substr(0, data_path_.size() - std::string("/value").size());
  if (step_rows_ != shape_[0]) return MismatchedClock{group + "/step", step_rows_};
  if (time_rows_ != shape_[0]) return MismatchedClock{group + "/time", time_rows_};
  return std::nullopt;
}

Shape Element::item() const { return timed_ ? Shape(shape_.begin() + 1, shape_.end()) : shape_; }

void Element::map_identity() { rows_.clear(); }

bool Element::map_by_step(const std::vector<std::int64_t>& frame_steps) {
  if (!timed_) return true;
  const auto first = steps_.begin(), last = steps_.begin() + static_cast<long>(samples_);
  if (std::equal(frame_steps.begin(), frame_steps.end(), first, last)) {
    rows_.clear();
    return true;
  }
  // H5MD steps rise: of a step written twice the second sample was left unread without a
  // word, and steps out of order were called a clock that misses some.
  const auto back = std::adjacent_find(first, last, std::greater_equal<>());
  if (back != last) {
    const std::string group =
        data_path_.substr(0, data_path_.size() - std::string("/value").size());
    throw Error(group + "/step: expected rising steps, got " + std::to_string(back[1]) +
                " at sample " + std::to_string(back - first + 1) + " after " +
                std::to_string(back[0]));
  }
  std::vector<hsize_t> rows;
  for (std::int64_t s : frame_steps) {
    auto it = std::lower_bound(first, last, s);
    if (it == last || *it != s) return false;
    rows.push_back(static_cast<hsize_t>(it - first));
  }
  rows_ = std::move(rows);
  return true;
}

hsize_t Element::row(long frame) const {
  return rows_.empty() ? static_cast<hsize_t>(frame) : rows_[static_cast<std::size_t>(frame)];
}

void Element::read(long frame, double* out) const {
  if (timed_) {
    read_rows(value_.id(), data_path_, H5T_NATIVE_DOUBLE, row(frame), 1, out);
  } else {
    read_all(value_.id(), data_path_, H5T_NATIVE_DOUBLE, out);
  }
}

std::vector<std::int64_t> Element::read_integers(long frame) const {
  if (timed_) return read_integer_rows(value_.id(), data_path_, row(frame), 1);
  return read_integer_rows(value_.id(), data_path_, 0, shape_.empty() ? 1 : shape_[0]);
}

}  // namespace granpipe::h5
