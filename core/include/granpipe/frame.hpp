#pragma once
// One configuration of particles: a particle table, an optional contact table, the
// container and per-frame observables, each table a set of named, typed columns
// (property_table.hpp) described by the standard properties or by the plugin that adds
// them (property.hpp).
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "granpipe/container.hpp"
#include "granpipe/property.hpp"
#include "granpipe/property_table.hpp"

namespace granpipe {

// What a particle touches or leans on: a particle index (>= 0), nothing, or a wall.
// One encoding serves contacts and support labels alike.
namespace partner {
constexpr std::int64_t none = -1;
constexpr std::int64_t wall(Wall w) { return -2 - static_cast<std::int64_t>(w); }
constexpr bool is_particle(std::int64_t p) { return p >= 0; }
// Exactly the codes of the walls there are: any other negative number is garbage, not a wall.
constexpr bool is_wall(std::int64_t p) {
  return p <= -2 && p > -2 - static_cast<std::int64_t>(Wall::Count);
}
constexpr Wall wall_of(std::int64_t p) { return static_cast<Wall>(-2 - p); }
}  // namespace partner

struct Frame {
  int dim = 3;
  // position, radius, id and species always, in that order; any other column may follow.
  PropertyTable particles{Scope::Particle};
  // i and j always (j a particle or a wall partner); overlap, forces, contact point and
  // plugin columns as the source provides them.
  std::optional<PropertyTable> contacts;
  // One row: tap, cycle, amplitude, energy, ... whatever the source counts per frame.
  PropertyTable observables{Scope::Frame, 1};
  Container container;
  double time = 0.0;
  std::int64_t step = 0;

  Frame() { resize(0, 3); }

  Eigen::Index size() const { return particles.rows(); }
  // Sizes the frame to n particles in `dimension` dimensions with the required columns
  // only (zero positions and radii, ids 0..n-1, species 0); drops every other column,
  // the contacts and the observables.
  void resize(Eigen::Index n, int dimension);

  // The required columns, by position in the table (no look-up by name).
  Coordinates& position() { return particles.column(0).as<Coordinates>(); }
  const Coordinates& position() const { return particles.column(0).as<Coordinates>(); }
  Eigen::ArrayXd& radius() { return particles.column(1).as<Eigen::ArrayXd>(); }
  const Eigen::ArrayXd& radius() const { return particles.column(1).as<Eigen::ArrayXd>(); }
  IndexArray& id() { return particles.column(2).as<IndexArray>(); }
  const IndexArray& id() const { return particles.column(2).as<IndexArray>(); }
  IntArray& species() { return particles.column(3).as<IntArray>(); }
  const IntArray& species() const { return particles.column(3).as<IntArray>(); }

  // Any other per-particle column: has("velocity"), get<double>("voronoi_volume") for
  // one component, table<double>("velocity") for several.
  bool has(std::string_view name) const { return particles.has(name); }
  template <class T>
  Values<T>& get(std::string_view name) {
    return particles.get<Values<T>>(name);
  }
  template <class T>
  const Values<T>& get(std::string_view name) const {
    return particles.get<Values<T>>(name);
  }
  template <class T>
  ValueTable<T>& table(std::string_view name) {
    return particles.get<ValueTable<T>>(name);
  }
  template <class T>
  const ValueTable<T>& table(std::string_view name) const {
    return particles.get<ValueTable<T>>(name);
  }
  // Adds a standard particle column (velocity, angular_velocity, force, ...) zero-filled.
  Column& add(std::string_view standard_name);

  // A contact table of m rows with i and j, replacing any earlier one.
  PropertyTable& add_contacts(Eigen::Index m);
  IndexArray& contact_i() { return contacts->column(0).as<IndexArray>(); }
  const IndexArray& contact_i() const { return contacts->column(0).as<IndexArray>(); }
  IndexArray& contact_j() { return contacts->column(1).as<IndexArray>(); }
  const IndexArray& contact_j() const { return contacts->column(1).as<IndexArray>(); }

  // Per-frame observables: set (adding it when new) and read back (nothing when absent).
  void set_observable(const Property& p, double value);
  void set_observable(const Property& p, std::int64_t value);
  std::optional<double> real_observable(std::string_view name) const;
  std::optional<std::int64_t> integer_observable(std::string_view name) const;

  // Throws InputError naming `where` on NaN/inf positions or radii, non-positive radii,
  // NaN/inf velocities, angular velocities, forces or torques, missing required columns,
  // columns of the wrong type or size, a container whose numbers are not finite or whose
  // sides are out of order (granpipe/container_check.hpp), or contacts naming a particle
  // that does not exist or a wall the container does not have.
  void check(const std::string& where) const;
  // The structural part of check(): dimension, required columns, every column's rows and
  // components. Values are not looked at (a frame store keeps NaNs as given).
  void check_layout(const std::string& where) const;
};

}  // namespace granpipe
