#include "granpipe/property.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace granpipe {

namespace {

constexpr int kDim = kDimComponents, kSpin = kSpinComponents;
using enum Scope;
using enum ValueType;

// The standard columns. H5MD names where H5MD has one (position, velocity, force, species,
// id); the required ones first, in the order Frame keeps them.
const std::array<Property, 15>& table() {
  static const std::array<Property, 15> t{{
      {"position", Particle, Real, kDim, "length", "particle centre"},
      {"radius", Particle, Real, 1, "length", "particle radius"},
      {"id", Particle, Integer, 1, "", "particle identifier, stable across frames"},
      {"species", Particle, Small, 1, "", "particle species (material) index"},
      {"velocity", Particle, Real, kDim, "length/time", "centre velocity"},
      {"angular_velocity", Particle, Real, kSpin, "1/time", "angular velocity (about z in 2D)"},
      {"force", Particle, Real, kDim, "force", "total force on the particle"},
      {"torque", Particle, Real, kSpin, "force*length", "total torque on the particle"},
      {"orientation", Particle, Real, 4, "1", "unit quaternion (w, x, y, z)"},
      {"i", Contact, Integer, 1, "", "first particle of the contact"},
      {"j", Contact, Integer, 1, "",
       "second particle, or a wall as -2 - wall number (docs/file-format.md)"},
      {"overlap", Contact, Real, 1, "length", "overlap R_i + R_j - |r_ij| (> 0 when pressed)"},
      {"normal_force", Contact, Real, kDim, "force", "normal force on i from j"},
      {"tangential_force", Contact, Real, kDim, "force", "tangential force on i from j"},
      {"point", Contact, Real, kDim, "length", "contact point"},
  }};
  return t;
}

}  // namespace

const char* to_string(Scope s) {
  switch (s) {
    case Scope::Particle:
      return "particle";
    case Scope::Contact:
      return "contact";
    case Scope::Frame:
      return "frame";
  }
  return "?";
}

const char* to_string(ValueType t) {
  switch (t) {
    case ValueType::Real:
      return "real";
    case ValueType::Integer:
      return "integer";
    case ValueType::Small:
      return "small integer";
  }
  return "?";
}

std::string describe_type(const Property& p) {
  std::string s = to_string(p.type);
  if (p.components == kDimComponents) return s + "[dim]";
  if (p.components == kSpinComponents) return s + "[3 in 3D, 1 in 2D]";
  if (p.components != 1) return s + "[" + std::to_string(p.components) + "]";
  return s;
}

bool is_required(const Property& p) {
  static const std::array<std::string_view, 4> particle{"position", "radius", "id", "species"};
  if (p.scope == Scope::Particle) {
    return std::find(particle.begin(), particle.end(), p.name) != particle.end();
  }
  return p.scope == Scope::Contact && (p.name == "i" || p.name == "j");
}

std::span<const Property> standard_properties() { return table(); }

const Property* find_standard(std::string_view name, Scope scope) {
  for (const Property& p : table()) {
    if (p.name == name && p.scope == scope) return &p;
  }
  return nullptr;
}

bool is_valid_column_name(std::string_view name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front()))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

bool is_reserved_column_name(std::string_view name, Scope scope) {
  switch (scope) {
    case Scope::Particle:
      return name == "box";
    case Scope::Contact:
      return name == "offset" || name == "count";
    default:
      return false;
  }
}

}  // namespace granpipe
