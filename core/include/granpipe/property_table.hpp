#pragma once
// Named, typed columns of one table of a frame (particles, contacts or per-frame
// observables), structure of arrays: each column one contiguous Eigen array.
//
// Invariants: every column has rows() rows; a column declared with one component is a
// vector (Values<T>), any other a rows x components array (ValueTable<T>), whatever the
// dimension (so a 2D angular velocity is still a table, of one column); names are unique.
// Columns live behind stable pointers: a reference to one stays valid while others are
// added or removed.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/property.hpp"

namespace granpipe {

template <class T>
using Values = Eigen::Array<T, Eigen::Dynamic, 1>;
template <class T>
using ValueTable = Eigen::Array<T, Eigen::Dynamic, Eigen::Dynamic>;

using Coordinates = ValueTable<double>;  // N x dim, each coordinate contiguous
using IndexArray = Values<std::int64_t>;
using IntArray = Values<std::int32_t>;

class Column {
 public:
  using Storage =
      std::variant<Values<double>, ValueTable<double>, Values<std::int64_t>,
                   ValueTable<std::int64_t>, Values<std::int32_t>, ValueTable<std::int32_t>>;

  // Zero-filled, `rows` rows, components as the property asks in dimension `dim`.
  Column(Property property, Eigen::Index rows, int dim);

  const Property& property() const { return property_; }
  const std::string& name() const { return property_.name; }
  Eigen::Index rows() const;
  int components() const;
  const Storage& storage() const { return data_; }
  Storage& storage() { return data_; }
  // Zero-filled with `rows` rows (contents are not kept).
  void reset(Eigen::Index rows);
  // Whether a PropertyTable handed this column out by name for writing (get<A>(name),
  // find(name), add() of an existing column): how the runner tells a published column
  // that publish() never filled.
  bool handed_out() const { return handed_out_; }

  // The values as array type A (Values<T> or ValueTable<T>); throws InternalError naming
  // the column when it holds another type, since that is a plugin's mistake.
  template <class A>
  A& as() {
    if (auto* a = std::get_if<A>(&data_)) return *a;
    throw_wrong_type(type_name<A>());
  }
  template <class A>
  const A& as() const {
    if (const auto* a = std::get_if<A>(&data_)) return *a;
    throw_wrong_type(type_name<A>());
  }

 private:
  template <class A>
  static std::string type_name();
  [[noreturn]] void throw_wrong_type(const std::string& asked) const;
  friend class PropertyTable;  // sets handed_out_
  Property property_;
  int dim_;
  bool handed_out_ = false;
  Storage data_;
};

class PropertyTable {
 public:
  explicit PropertyTable(Scope scope = Scope::Particle, Eigen::Index rows = 0, int dim = 3)
      : scope_(scope), rows_(rows), dim_(dim) {}
  PropertyTable(const PropertyTable& other);
  PropertyTable& operator=(const PropertyTable& other);
  PropertyTable(PropertyTable&&) noexcept = default;
  PropertyTable& operator=(PropertyTable&&) noexcept = default;

  Scope scope() const { return scope_; }
  Eigen::Index rows() const { return rows_; }
  int dim() const { return dim_; }
  std::size_t size() const { return columns_.size(); }
  const Column& column(std::size_t k) const { return *columns_[k]; }
  Column& column(std::size_t k) { return *columns_[k]; }

  bool has(std::string_view name) const { return find(name) != nullptr; }
  const Column* find(std::string_view name) const;
  Column* find(std::string_view name);

  // Adds a zero-filled column, or returns the one of that name when it matches the
  // property; a column of that name but another type is an InternalError.
  Column& add(const Property& property);
  template <class A>
  A& add(const Property& property) {
    return add(property).template as<A>();
  }
  template <class A>
  A& get(std::string_view name) {
    return require(name).template as<A>();
  }
  template <class A>
  const A& get(std::string_view name) const {
    return require(name).template as<A>();
  }
  void remove(std::string_view name);
  // Every column zero-filled with `rows` rows.
  void reset(Eigen::Index rows);
  // Drops every column; rows and dim as given.
  void clear(Eigen::Index rows, int dim);

 private:
  const Column& require(std::string_view name) const;
  Column& require(std::string_view name);
  Scope scope_;
  Eigen::Index rows_;
  int dim_;
  std::vector<std::unique_ptr<Column>> columns_;
};

template <class A>
std::string Column::type_name() {
  using T = typename A::Scalar;
  std::string base = std::is_same_v<T, double>         ? "real"
                     : std::is_same_v<T, std::int64_t> ? "integer"
                                                       : "small";
  return A::ColsAtCompileTime == 1 ? base : base + "[components]";
}

}  // namespace granpipe
