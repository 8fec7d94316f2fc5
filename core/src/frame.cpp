#include "granpipe/frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "granpipe/container_check.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {

namespace {

const Property& standard(std::string_view name, Scope scope) {
  if (const Property* p = find_standard(name, scope)) return *p;
  throw InternalError("\"" + std::string(name) + "\" is not a standard " + to_string(scope) +
                      " property");
}

std::string describe_particle(const Frame& f, Eigen::Index k) {
  std::ostringstream s;
  s << "particle " << k << " (id " << f.id()[k] << ")";
  return s.str();
}

// Every column of a table has its rows and the components its property asks for.
void check_table(const PropertyTable& t, int dim, const std::string& where) {
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Column& c = t.column(k);
    if (c.rows() != t.rows()) {
      throw InputError(where + ": column \"" + c.name() + "\" has " + std::to_string(c.rows()) +
                       " rows, expected " + std::to_string(t.rows()) + " (one per " +
                       to_string(t.scope()) + ")");
    }
    if (c.components() != c.property().components_in(dim)) {
      throw InputError(where + ": column \"" + c.name() + "\" has " +
                       std::to_string(c.components()) + " components, expected " +
                       std::to_string(c.property().components_in(dim)));
    }
  }
}

void check_required_particle_columns(const Frame& f, const std::string& where) {
  const char* names[] = {"position", "radius", "id", "species"};
  for (std::size_t k = 0; k < 4; ++k) {
    if (f.particles.size() <= k || f.particles.column(k).name() != names[k] ||
        !f.particles.column(k).property().matches(standard(names[k], Scope::Particle))) {
      throw InternalError(where +
                          ": the particle table does not start with position, radius, "
                          "id and species");
    }
  }
}

void check_contacts(const Frame& f, const std::string& where) {
  const Eigen::Index n = f.size();
  const IndexArray &i = f.contact_i(), &j = f.contact_j();
  for (Eigen::Index k = 0; k < i.size(); ++k) {
    const bool partner = (partner::is_particle(j[k]) && j[k] < n) || partner::is_wall(j[k]);
    if (i[k] < 0 || i[k] >= n || !partner) {
      throw InputError(where + ": contact " + std::to_string(k) +
                       ": expected particle indices below " + std::to_string(n) +
                       " (or a wall code -2 to -8 as second partner), got " + std::to_string(i[k]) +
                       " and " + std::to_string(j[k]));
    }
    // A contact with a wall the container does not have was counted as a wall contact.
    if (partner::is_wall(j[k]) && !has_wall(f.container, f.dim, partner::wall_of(j[k]))) {
      throw InputError(where + ": contact " + std::to_string(k) + ": expected a wall of the " +
                       to_string(f.container.shape) + " container as second partner, got " +
                       to_string(partner::wall_of(j[k])) + " (code " + std::to_string(j[k]) +
                       "), which it does not have");
    }
  }
}

// A table whose rows name (i, j) in strictly increasing order, each particle pair with
// i < j (a simulator's own, as the dem source writes it), repeats no contact: seen in one
// pass, without the sorts' copies of the rows below (tens of MB for a million spheres, on
// top of the frame).
bool rows_strictly_increasing(const IndexArray& i, const IndexArray& j) {
  for (Eigen::Index k = 0; k < i.size(); ++k) {
    if (partner::is_particle(j[k]) && i[k] >= j[k]) return false;
    if (k > 0 && (i[k] < i[k - 1] || (i[k] == i[k - 1] && j[k] <= j[k - 1]))) return false;
  }
  return true;
}

// A contact row by its partners, then its index in the table.
using RowKey = std::tuple<std::int64_t, std::int64_t, Eigen::Index>;

// The particle pairs' rows as (smaller, larger, row), or the wall contacts' as (particle,
// wall, row), sorted: rows naming one contact come together.
std::vector<RowKey> sorted_rows(const Frame& f, bool walls) {
  const IndexArray &i = f.contact_i(), &j = f.contact_j();
  std::vector<RowKey> rows;
  for (Eigen::Index k = 0; k < i.size(); ++k) {
    if (partner::is_particle(j[k]) == walls) continue;
    if (walls) {
      rows.emplace_back(i[k], j[k], k);
    } else {
      rows.emplace_back(std::min(i[k], j[k]), std::max(i[k], j[k]), k);
    }
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

// Each pair of particles in one row: a pair in two, as (i, j) and (j, i) or repeated, counted
// twice in every coordination, network and force statistic (an H5MD file's table listing
// each pair both ways doubled z).
void check_each_pair_once(const Frame& f, const std::string& where) {
  const std::vector<RowKey> pairs = sorted_rows(f, false);
  for (std::size_t n = 1; n < pairs.size(); ++n) {
    const auto [a, b, row] = pairs[n];
    const auto [a0, b0, row0] = pairs[n - 1];
    if (a != a0 || b != b0) continue;
    throw InputError(where + ": contacts " + std::to_string(row0) + " and " + std::to_string(row) +
                     ": expected each pair of particles once, got " + std::to_string(a) + " and " +
                     std::to_string(b) + " in both (a table listing each pair both ways?)");
  }
}

// Whether rows a and b of the table hold the same bits in every column (NaN, a value a
// file leaves out, equal to itself).
bool same_row(const PropertyTable& table, Eigen::Index a, Eigen::Index b) {
  for (std::size_t c = 0; c < table.size(); ++c) {
    const bool same = std::visit(
        [&](const auto& v) {
          for (Eigen::Index k = 0; k < v.cols(); ++k)
            if (std::memcmp(&v(a, k), &v(b, k), sizeof(v(a, k))) != 0) return false;
          return true;
        },
        table.column(c).storage());
    if (!same) return false;
  }
  return true;
}

// A particle may touch one wall in several rows (a wall made of a mesh touches it at each
// facet: LIGGGHTS' wall contacts), but not twice with the same values: a row written twice
// doubled the base contacts and the wall's forces (an H5MD file, a LIGGGHTS wall dump; exit
// 0). A table of i and j alone cannot tell two facets from a repeated row.
void check_each_wall_contact_once(const Frame& f, const std::string& where) {
  if (f.contacts->size() <= 2) return;
  const std::vector<RowKey> rows = sorted_rows(f, true);
  std::size_t group = 0;  // the first row of this (particle, wall)
  for (std::size_t n = 1; n < rows.size(); ++n) {
    const auto [a, w, row] = rows[n];
    if (a != std::get<0>(rows[group]) || w != std::get<1>(rows[group])) {
      group = n;
      continue;
    }
    for (std::size_t m = group; m < n; ++m) {
      const Eigen::Index earlier = std::get<2>(rows[m]);
      if (!same_row(*f.contacts, earlier, row)) continue;
      throw InputError(where + ": contacts " + std::to_string(earlier) + " and " +
                       std::to_string(row) + ": expected each contact once, got " +
                       describe_particle(f, a) + " against the wall " +
                       to_string(partner::wall_of(w)) + " in both with the same values (a row " +
                       "written twice?)");
    }
  }
}

void check_each_contact_once(const Frame& f, const std::string& where) {
  if (rows_strictly_increasing(f.contact_i(), f.contact_j())) return;
  check_each_pair_once(f, where);
  check_each_wall_contact_once(f, where);
}

// The first value of a real column that is not finite: its row, component and value.
struct NotFinite {
  Eigen::Index row = 0, component = 0;
  double value = 0.0;
};
std::optional<NotFinite> first_not_finite(const Column& c) {
  return std::visit(
      [](const auto& values) -> std::optional<NotFinite> {
        using Scalar = typename std::decay_t<decltype(values)>::Scalar;
        if constexpr (std::is_same_v<Scalar, double>) {
          for (Eigen::Index k = 0; k < values.rows(); ++k)
            for (Eigen::Index a = 0; a < values.cols(); ++a)
              if (!std::isfinite(values(k, a))) return NotFinite{k, a, values(k, a)};
        }
        return std::nullopt;
      },
      c.storage());
}

// The motion a simulator starts from and writers pass on, and the forces and places of
// the contacts: a NaN there is a broken file, never a value (positions and radii are
// checked apart, with their own words). An H5MD file's contact force of inf went into the
// networks' statistics, exit 0.
void check_motion(const Frame& f, const std::string& where) {
  for (const char* name : {"velocity", "angular_velocity", "force", "torque"}) {
    const Column* c = f.particles.find(name);
    const auto bad = c ? first_not_finite(*c) : std::nullopt;
    if (!bad) continue;
    std::ostringstream s;
    s << where << ": " << describe_particle(f, bad->row) << ": expected a finite " << name
      << ", got " << bad->value << " in component " << bad->component;
    throw InputError(s.str());
  }
}

void check_contact_values(const Frame& f, const std::string& where) {
  for (const char* name : {"overlap", "normal_force", "tangential_force", "point"}) {
    const Column* c = f.contacts->find(name);
    const auto bad = c ? first_not_finite(*c) : std::nullopt;
    if (!bad) continue;
    std::ostringstream s;
    s << where << ": contact " << bad->row << ": expected a finite " << name << ", got "
      << bad->value;
    if (c->components() > 1) s << " in component " << bad->component;
    throw InputError(s.str());
  }
}

// Sizes and places a double computes with: a sphere's volume, a squared distance and an
// overlap stay finite and normal within them (a radius of 1e-320 had a volume of 0, centres
// 1e300 apart a squared distance of infinity).
constexpr double kSmallestRadius = 1e-100, kLargestLength = 1e100;

void check_particles(const Frame& f, const std::string& where) {
  const Coordinates& x = f.position();
  const Eigen::ArrayXd& r = f.radius();
  auto refuse = [&](Eigen::Index k, const std::string& expected, double got,
                    const std::string& tail) {
    std::ostringstream s;
    s << where << ": " << describe_particle(f, k) << ": expected " << expected << ", got " << got
      << tail;
    throw InputError(s.str());
  };
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    for (int a = 0; a < f.dim; ++a) {
      const std::string coordinate = std::string(" in coordinate ") + "xyz"[a];
      if (!std::isfinite(x(k, a))) refuse(k, "a finite position", x(k, a), coordinate);
      if (std::abs(x(k, a)) > kLargestLength)
        refuse(k, "a position within +-1e+100", x(k, a), coordinate);
    }
    if (!(r[k] > 0.0) || !std::isfinite(r[k])) refuse(k, "a finite radius > 0", r[k], "");
    if (r[k] < kSmallestRadius || r[k] > kLargestLength)
      refuse(k, "a radius from 1e-100 to 1e+100", r[k], "");
    // Species index tables (densities, materials, the analyzers' per-species counts): a
    // negative one was read by some and passed by others.
    if (f.species()[k] < 0) refuse(k, "a species >= 0", f.species()[k], "");
    // Wider than a periodic box, a particle overlaps its own image: no measure holds.
    for (int a = 0; a < f.dim; ++a) {
      const double length = f.container.length(a), diameter = 2.0 * r[k];
      if (!f.container.periodic(a) || diameter <= length) continue;
      throw InputError(where + ": " + describe_particle(f, k) +
                       ": expected a diameter of at most the periodic box's length along " +
                       "xyz"[a] + ", " + format_apart(length, diameter) + ", got " +
                       format_apart(diameter, length) + " (it would overlap its own image)");
    }
  }
}

}  // namespace

void Frame::resize(Eigen::Index n, int dimension) {
  dim = dimension;
  particles.clear(n, dimension);
  for (const char* name : {"position", "radius", "id", "species"}) {
    particles.add(standard(name, Scope::Particle));
  }
  id() = IndexArray::LinSpaced(n, 0, n - 1);
  contacts.reset();
  observables.clear(1, dimension);
}

Column& Frame::add(std::string_view standard_name) {
  return particles.add(standard(standard_name, Scope::Particle));
}

PropertyTable& Frame::add_contacts(Eigen::Index m) {
  contacts.emplace(Scope::Contact, m, dim);
  contacts->add(standard("i", Scope::Contact));
  contacts->add(standard("j", Scope::Contact));
  return *contacts;
}

void Frame::set_observable(const Property& p, double value) {
  observables.add<Eigen::ArrayXd>(p)[0] = value;
}

void Frame::set_observable(const Property& p, std::int64_t value) {
  observables.add<IndexArray>(p)[0] = value;
}

std::optional<double> Frame::real_observable(std::string_view name) const {
  const Column* c = observables.find(name);
  if (!c || c->property().type != ValueType::Real || c->property().components != 1) return {};
  return c->as<Eigen::ArrayXd>()[0];
}

std::optional<std::int64_t> Frame::integer_observable(std::string_view name) const {
  const Column* c = observables.find(name);
  if (!c || c->property().type != ValueType::Integer || c->property().components != 1) return {};
  return c->as<IndexArray>()[0];
}

void Frame::check_layout(const std::string& where) const {
  if (dim != 2 && dim != 3) {
    throw InputError(where + ": expected dimension 2 or 3, got " + std::to_string(dim));
  }
  check_required_particle_columns(*this, where);
  check_table(particles, dim, where);
  check_table(observables, dim, where);
  if (contacts) {
    check_table(*contacts, dim, where + ": contacts");
    if (contacts->size() < 2 || contacts->column(0).name() != "i" ||
        contacts->column(1).name() != "j") {
      throw InternalError(where + ": the contact table does not start with i and j");
    }
  }
}

void Frame::check(const std::string& where) const {
  check_layout(where);
  check_container_values(container, dim, where);
  if (contacts) {
    check_contacts(*this, where);
    check_each_contact_once(*this, where);
    check_contact_values(*this, where);
  }
  check_particles(*this, where);
  check_motion(*this, where);
}

}  // namespace granpipe
