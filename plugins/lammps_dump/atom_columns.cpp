#include "atom_columns.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <utility>

#include "granpipe/errors.hpp"

namespace granpipe::lammps_dump {

namespace {

using Names = std::array<const char*, 3>;

// The frame's vector columns and the dump columns of their components.
const std::array<std::pair<const char*, Names>, 4> kVectors{{
    {"velocity", {"vx", "vy", "vz"}},
    {"angular_velocity", {"omegax", "omegay", "omegaz"}},
    {"force", {"fx", "fy", "fz"}},
    {"torque", {"tqx", "tqy", "tqz"}},
}};

// Position columns by preference: as written, then those that need the box.
const std::array<std::pair<Coordinate, Names>, 4> kPositions{{
    {Coordinate::Plain, {"x", "y", "z"}},
    {Coordinate::Unwrapped, {"xu", "yu", "zu"}},
    {Coordinate::Scaled, {"xs", "ys", "zs"}},
    {Coordinate::ScaledUnwrapped, {"xsu", "ysu", "zsu"}},
}};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : " ") + n;
  return s;
}

// A dump column's name as a frame column's: c_stress[1] -> c_stress_1.
std::string kept_name(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (c == ']') continue;
    out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
  }
  return out;
}

// The dump's columns by name, each taken at most once.
class ColumnFinder {
 public:
  ColumnFinder(const std::vector<std::string>& names, const std::string& at)
      : used_(names.size(), false) {
    for (std::size_t k = 0; k < names.size(); ++k) {
      const auto [seen, fresh] = index_.emplace(names[k], static_cast<int>(k));
      if (!fresh) {
        throw InputError(at + "expected each column once in \"ITEM: ATOMS\", got \"" + names[k] +
                         "\" as columns " + std::to_string(seen->second + 1) + " and " +
                         std::to_string(k + 1));
      }
    }
  }
  // The column of this name, marked as used, or -1.
  int take(const std::string& name) {
    const auto it = index_.find(name);
    if (it == index_.end()) return -1;
    used_[static_cast<std::size_t>(it->second)] = true;
    return it->second;
  }
  bool used(std::size_t k) const { return used_[k]; }

 private:
  std::map<std::string, int> index_;
  std::vector<bool> used_;
};

void find_positions(ColumnFinder& find, AtomColumns& c, const std::string& at) {
  for (std::size_t a = 0; a < 3; ++a) {
    for (const auto& [kind, names] : kPositions) {
      c.position[a] = find.take(names[a]);
      c.coordinate[a] = kind;
      if (c.position[a] >= 0) break;
    }
    // x and y without z: a 2D run's dump, not one missing a column.
    if (c.position[a] < 0 && a == 2) {
      throw InputError(at + kReads3d + "positions along x and y only (\"" + joined(c.names) +
                       "\"): a 2D run's dump");
    }
    if (c.position[a] < 0) {
      const std::string axis = kPositions[0].second[a];
      throw InputError(at + "expected a position column along " + axis + " (" + axis + ", " + axis +
                       "u, " + axis + "s or " + axis + "su), got \"" + joined(c.names) + "\"");
    }
  }
}

void find_vectors(ColumnFinder& find, AtomColumns& c, const std::string& at) {
  for (const auto& [frame_name, names] : kVectors) {
    VectorColumn v{frame_name, {find.take(names[0]), find.take(names[1]), find.take(names[2])}};
    const auto found = std::count_if(v.at.begin(), v.at.end(), [](int k) { return k >= 0; });
    if (found == 3) c.vectors.push_back(v);
    if (found != 0 && found != 3) {
      throw InputError(at + "expected " + names[0] + ", " + names[1] + " and " + names[2] +
                       " together, got " + std::to_string(found) + " of them in \"" +
                       joined(c.names) + "\"");
    }
  }
}

// Every column not read above, but those of text (element names).
void keep_the_others(const ColumnFinder& find, AtomColumns& c, const std::string& at) {
  std::map<std::string, std::string> kept;  // frame name -> dump name
  for (std::size_t k = 0; k < c.names.size(); ++k) {
    if (find.used(k) || c.names[k] == "element") continue;
    const std::string name = kept_name(c.names[k]);
    const bool standard = find_standard(name, Scope::Particle) != nullptr;
    const auto [other, fresh] = kept.emplace(name, c.names[k]);
    const bool reserved = is_reserved_column_name(name, Scope::Particle);
    if (!is_valid_column_name(name) || standard || !fresh || reserved) {
      const std::string why = standard   ? "a standard column's name"
                              : !fresh   ? "the name of column \"" + other->second + "\""
                              : reserved ? "the name of the frames file's box"
                                         : "not a column name";
      throw InputError(at + "expected a column name granpipe can keep, got \"" + c.names[k] +
                       "\" (kept as \"" + name + "\": " + why + ")");
    }
    c.kept.push_back(
        {Property{name, Scope::Particle, ValueType::Real, 1, "", "the dump's column " + c.names[k]},
         static_cast<int>(k)});
  }
}

}  // namespace

std::vector<Property> AtomColumns::properties() const {
  std::vector<Property> out;
  for (const VectorColumn& v : vectors) out.push_back(*find_standard(v.name, Scope::Particle));
  for (const KeptColumn& k : kept) out.push_back(k.property);
  return out;
}

AtomColumns parse_atom_columns(const std::vector<std::string>& names, const std::string& at) {
  AtomColumns c;
  c.names = names;
  c.count = names.size();
  ColumnFinder find(names, at);
  c.id = find.take("id");
  if (c.id < 0) throw InputError(at + "expected an id column, got \"" + joined(names) + "\"");
  c.type = find.take("type");
  find_positions(find, c, at);
  c.size = find.take("radius");
  const int diameter = find.take("diameter");
  // Both, and one would be read while the other said something else.
  if (c.size >= 0 && diameter >= 0) {
    throw InputError(at + "expected a radius or a diameter column, got both (\"" + joined(names) +
                     "\")");
  }
  if (c.size < 0) {
    c.size = diameter;
    c.diameter = c.size >= 0;
  }
  find_vectors(find, c, at);
  keep_the_others(find, c, at);
  return c;
}

}  // namespace granpipe::lammps_dump
