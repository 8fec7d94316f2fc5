#pragma once
// What a column of a frame is: its name, the table it belongs to, its value type, how
// many components it has and its unit. One table of these descriptors (standard_properties)
// drives the frame checks, the frames.h5 writer and reader, what sources provide and
// analyzers need, `granpipe inspect` and docs/file-format.md. Plugins describe their own
// columns with the same struct.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace granpipe {

// The table a column lives in: one row per particle, per contact, or one row per frame
// (observables such as a tap number or an amplitude).
enum class Scope : std::uint8_t { Particle, Contact, Frame };

// Stored values: double, 64-bit integer (indices, ids, partner codes), 32-bit integer
// (species, small labels).
enum class ValueType : std::uint8_t { Real, Integer, Small };

// Components of a vector column whose size follows the frame: `dim` for positions and
// forces, 3 in 3D and 1 in 2D for rotations (an angular velocity in the plane is a scalar).
inline constexpr int kDimComponents = -1;
inline constexpr int kSpinComponents = -2;

struct Property {
  std::string name;
  Scope scope = Scope::Particle;
  ValueType type = ValueType::Real;
  int components = 1;  // or kDimComponents / kSpinComponents
  std::string unit;    // "length", "length/time", "force", "1" (dimensionless), "" (a label)
  std::string doc;     // one line, shown by `granpipe inspect` and `describe`

  // Components in a frame of dimension `dim`.
  int components_in(int dim) const {
    if (components == kDimComponents) return dim;
    if (components == kSpinComponents) return dim == 3 ? 3 : 1;
    return components;
  }
  // True when values of `other` can be read as this property (name, scope, type and
  // components agree; units and docs are documentation).
  bool matches(const Property& other) const {
    return name == other.name && scope == other.scope && type == other.type &&
           components == other.components;
  }
};

const char* to_string(Scope s);
const char* to_string(ValueType t);
// "real[dim]", "integer", "small[2]": the type as `describe` and `inspect` show it.
std::string describe_type(const Property& p);

// Columns every frame has: position, radius, id, species (particles); i and j (contacts).
bool is_required(const Property& p);

// The standard properties: the one place that names them (adding one is one line in
// property.cpp). Plugins may add columns of any other name.
std::span<const Property> standard_properties();
// The standard property of this name and scope, or nullptr.
const Property* find_standard(std::string_view name, Scope scope);

// A name fit for a column and for an HDF5 path: letters, digits and '_', not starting
// with a digit.
bool is_valid_column_name(std::string_view name);

// A name the frames file gives a dataset of its own beside the columns of this scope
// ("box" beside the particles' columns, "offset" and "count" beside the contacts'): a
// column of that name cannot be stored.
bool is_reserved_column_name(std::string_view name, Scope scope);

}  // namespace granpipe
