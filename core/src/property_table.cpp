#include "granpipe/property_table.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "did_you_mean.hpp"

namespace granpipe {

namespace {

template <class T>
Column::Storage zeros(bool vector, Eigen::Index rows, int components) {
  if (vector) return Values<T>(Values<T>::Zero(rows));
  return ValueTable<T>(ValueTable<T>::Zero(rows, components));
}

}  // namespace

Column::Column(Property property, Eigen::Index rows, int dim)
    : property_(std::move(property)), dim_(dim) {
  reset(rows);
}

void Column::reset(Eigen::Index rows) {
  const bool vector = property_.components == 1;
  const int c = property_.components_in(dim_);
  switch (property_.type) {
    case ValueType::Real:
      data_ = zeros<double>(vector, rows, c);
      break;
    case ValueType::Integer:
      data_ = zeros<std::int64_t>(vector, rows, c);
      break;
    case ValueType::Small:
      data_ = zeros<std::int32_t>(vector, rows, c);
      break;
  }
}

Eigen::Index Column::rows() const {
  return std::visit([](const auto& a) -> Eigen::Index { return a.rows(); }, data_);
}

int Column::components() const {
  return std::visit([](const auto& a) { return static_cast<int>(a.cols()); }, data_);
}

void Column::throw_wrong_type(const std::string& asked) const {
  throw InternalError("column \"" + property_.name + "\" holds " + describe_type(property_) +
                      " values, read as " + asked);
}

PropertyTable::PropertyTable(const PropertyTable& other)
    : scope_(other.scope_), rows_(other.rows_), dim_(other.dim_) {
  columns_.reserve(other.columns_.size());
  for (const auto& c : other.columns_) columns_.push_back(std::make_unique<Column>(*c));
}

PropertyTable& PropertyTable::operator=(const PropertyTable& other) {
  if (this != &other) *this = PropertyTable(other);
  return *this;
}

const Column* PropertyTable::find(std::string_view name) const {
  for (const auto& c : columns_) {
    if (c->name() == name) return c.get();
  }
  return nullptr;
}

Column* PropertyTable::find(std::string_view name) {
  Column* c = const_cast<Column*>(std::as_const(*this).find(name));
  if (c) c->handed_out_ = true;
  return c;
}

Column& PropertyTable::add(const Property& property) {
  if (property.scope != scope_) {
    throw InternalError("column \"" + property.name + "\" is a " + to_string(property.scope) +
                        " property, added to the " + to_string(scope_) + " table");
  }
  if (Column* c = find(property.name)) {
    if (!c->property().matches(property)) {
      throw InternalError("column \"" + property.name + "\" exists as " +
                          describe_type(c->property()) + ", added again as " +
                          describe_type(property));
    }
    c->handed_out_ = true;
    return *c;
  }
  if (!is_valid_column_name(property.name) ||
      is_reserved_column_name(property.name, property.scope)) {
    throw InternalError("\"" + property.name +
                        "\" is not a column name (letters, digits and _, not starting with a "
                        "digit, and not a name the frames file keeps for itself)");
  }
  columns_.push_back(std::make_unique<Column>(property, rows_, dim_));
  return *columns_.back();
}

void PropertyTable::remove(std::string_view name) {
  std::erase_if(columns_, [&](const auto& c) { return c->name() == name; });
}

void PropertyTable::reset(Eigen::Index rows) {
  rows_ = rows;
  for (auto& c : columns_) c->reset(rows);
}

void PropertyTable::clear(Eigen::Index rows, int dim) {
  columns_.clear();
  rows_ = rows;
  dim_ = dim;
}

const Column& PropertyTable::require(std::string_view name) const {
  if (const Column* c = find(name)) return *c;
  std::vector<std::string> names;
  for (const auto& c : columns_) names.push_back(c->name());
  throw InternalError(std::string("the ") + to_string(scope_) + " table has no column \"" +
                      std::string(name) + "\"" + did_you_mean(std::string(name), names) +
                      known_list(names));
}

Column& PropertyTable::require(std::string_view name) {
  Column& c = const_cast<Column&>(std::as_const(*this).require(name));
  c.handed_out_ = true;
  return c;
}

}  // namespace granpipe
