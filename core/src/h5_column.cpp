#include "h5_column.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "granpipe/format_number.hpp"
#include "granpipe/property.hpp"

namespace granpipe::h5 {

namespace {

const char* const kComponentsAttr = "granpipe_components";
// A column's dimension ("length", "length/time"). H5MD's `unit` attribute holds unit
// strings ("nm", "ps"), which reduced units do not have: MDAnalysis refuses a file whose
// `unit` reads "length", so granpipe leaves `unit` out and keeps the dimension under its
// own name. Earlier granpipe files and other tools' files carry `unit`, read as before.
const char* const kDimensionAttr = "granpipe_dimension";
const char* const kUnitAttr = "unit";
const char* const kDocAttr = "description";

template <class T>
hid_t memory_type() {
  if constexpr (std::is_same_v<T, double>) return H5T_NATIVE_DOUBLE;
  if constexpr (std::is_same_v<T, std::int64_t>) return H5T_NATIVE_INT64;
  if constexpr (std::is_same_v<T, std::int32_t>) return H5T_NATIVE_INT32;
}

template <class T>
using RowMajor = Eigen::Array<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The whole numbers of a dataset of reals; HDF5 would truncate 1.5 to 1 without a word.
std::vector<std::int64_t> whole_numbers(hid_t dataset, const std::string& path, hsize_t first,
                                        hsize_t count, std::size_t values) {
  std::vector<double> reals(values);
  read_rows(dataset, path, H5T_NATIVE_DOUBLE, first, count, reals.data());
  std::vector<std::int64_t> out(values);
  for (std::size_t k = 0; k < values; ++k) {
    if (reals[k] != std::floor(reals[k]) || !(std::abs(reals[k]) < 0x1p63)) {
      throw Error(path + ": expected whole numbers, got " + format_number(reals[k]));
    }
    out[k] = static_cast<std::int64_t>(reals[k]);
  }
  return out;
}

// Integers into an integer column: HDF5 converts reals by truncation and integers beyond
// the column's type to its nearest bound (a species 2^40 read as 2147483647), both without a
// word. Read wide, then checked.
template <class T>
void read_integers(hid_t dataset, const std::string& path, hsize_t first, hsize_t count, T* out,
                   std::size_t values) {
  Object type = owned(H5Dget_type(dataset), path + ": cannot read the data type");
  const std::vector<std::int64_t> wide = H5Tget_class(type.id()) == H5T_FLOAT
                                             ? whole_numbers(dataset, path, first, count, values)
                                             : read_integer_rows(dataset, path, first, count);
  constexpr auto lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
  for (std::size_t k = 0; k < values; ++k) {
    if (wide[k] < lo || wide[k] > hi) {
      throw Error(path + ": expected integers from " + std::to_string(lo) + " to " +
                  std::to_string(hi) + ", got " + std::to_string(wide[k]));
    }
    out[k] = static_cast<T>(wide[k]);
  }
}

template <class T>
void read_values(hid_t dataset, const std::string& path, hsize_t first, hsize_t count, T* out,
                 std::size_t values) {
  if constexpr (std::is_integral_v<T>) {
    read_integers(dataset, path, first, count, out, values);
  } else {
    read_rows(dataset, path, memory_type<T>(), first, count, out);
  }
}

}  // namespace

hid_t file_type(ValueType t) {
  switch (t) {
    case ValueType::Real:
      return H5T_IEEE_F64LE;
    case ValueType::Integer:
      return H5T_STD_I64LE;
    case ValueType::Small:
      return H5T_STD_I32LE;
  }
  return H5T_IEEE_F64LE;
}

ValueType value_type_of(hid_t dataset, const std::string& path) {
  Object type = owned(H5Dget_type(dataset), path + ": cannot read the type");
  switch (H5Tget_class(type.id())) {
    case H5T_FLOAT:
      return ValueType::Real;
    case H5T_INTEGER:
      return H5Tget_size(type.id()) > 4 ? ValueType::Integer : ValueType::Small;
    case H5T_ENUM:
      return ValueType::Small;
    default:
      throw Error(path + ": expected numbers, got another HDF5 type");
  }
}

Shape item_shape(const Column& c) {
  if (c.property().components == 1) return {};
  return {static_cast<hsize_t>(c.components())};
}

namespace {

// A column of several components is held component by component (Eigen's order) and
// stored row by row (HDF5's, C order), so it is written through a copy. Where each of its
// rows is a row of the series (a contact table), the copy is made in blocks of rows: a
// table of millions of contacts is then not held twice, nor are HDF5's selections of
// every chunk it touches. Where the whole column is one row of the series (a frame's
// particles, one chunk), it is written at once: a block would read that chunk back.
template <class A>
void append_components(hid_t dataset, const std::string& path, const A& a, hsize_t rows) {
  using T = typename A::Scalar;
  constexpr Eigen::Index kBlockRows = Eigen::Index{1} << 16;
  if (rows != static_cast<hsize_t>(a.rows())) {
    const RowMajor<T> rows_first = a;
    append_rows(dataset, path, memory_type<T>(), rows_first.data(), rows);
    return;
  }
  for (Eigen::Index first = 0; first < a.rows(); first += kBlockRows) {
    const Eigen::Index count = std::min(kBlockRows, a.rows() - first);
    const RowMajor<T> block = a.middleRows(first, count);
    append_rows(dataset, path, memory_type<T>(), block.data(), static_cast<hsize_t>(count));
  }
}

}  // namespace

void append_column(hid_t dataset, const std::string& path, const Column& c, hsize_t rows) {
  std::visit(
      [&](const auto& a) {
        using A = std::decay_t<decltype(a)>;
        using T = typename A::Scalar;
        if constexpr (A::ColsAtCompileTime == 1) {
          append_rows(dataset, path, memory_type<T>(), a.data(), rows);
        } else {
          append_components(dataset, path, a, rows);
        }
      },
      c.storage());
}

void read_column(hid_t dataset, const std::string& path, hsize_t first, hsize_t count, Column& c) {
  std::visit(
      [&](auto& a) {
        using A = std::decay_t<decltype(a)>;
        using T = typename A::Scalar;
        const auto values = static_cast<std::size_t>(a.size());
        if constexpr (A::ColsAtCompileTime == 1) {
          read_values(dataset, path, first, count, a.data(), values);
        } else {
          RowMajor<T> rows_first(a.rows(), a.cols());
          read_values(dataset, path, first, count, rows_first.data(), values);
          a = rows_first;
        }
      },
      c.storage());
}

void write_property_attributes(hid_t dataset, const Property& p) {
  write_attribute(dataset, kComponentsAttr, p.components);
  if (!p.unit.empty()) write_attribute(dataset, kDimensionAttr, p.unit);
  if (!p.doc.empty()) write_text_attribute(dataset, kDocAttr, p.doc);
}

Property read_property(hid_t dataset, const std::string& path, const std::string& name, Scope scope,
                       const Shape& item, int dim) {
  if (const Property* p = find_standard(name, scope)) return *p;
  // Analyzers and writers name columns in JSON paths and file headers: another tool's
  // element "a b" would break them.
  if (!is_valid_column_name(name)) {
    throw Error(path +
                ": expected an element name of letters, digits and _, not starting "
                "with a digit (a column's name), got \"" +
                name + "\"");
  }
  Property p{name, scope, value_type_of(dataset, path), 1, "", ""};
  if (has_attribute(dataset, kComponentsAttr)) {
    p.components = static_cast<int>(read_integer_attribute(dataset, path, kComponentsAttr).at(0));
  } else if (item.size() == 1) {
    p.components = static_cast<int>(item[0]);
  }
  if (item.size() > 1 || (item.empty() != (p.components == 1)) ||
      (!item.empty() && static_cast<int>(item[0]) != p.components_in(dim))) {
    throw Error(path + ": expected one value or one vector per " + std::string(to_string(scope)) +
                ", got rows of shape " + format_shape(item));
  }
  for (const char* attr : {kDimensionAttr, kUnitAttr}) {
    if (has_attribute(dataset, attr)) {
      p.unit = read_string_attribute(dataset, path, attr).at(0);
      break;
    }
  }
  if (has_attribute(dataset, kDocAttr))
    p.doc = read_string_attribute(dataset, path, kDocAttr).at(0);
  return p;
}

}  // namespace granpipe::h5
