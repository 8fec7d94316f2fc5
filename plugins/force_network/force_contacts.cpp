#include "force_contacts.hpp"

#include <cmath>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "granpipe/loaded_pair_contacts.hpp"

namespace granpipe::force_network {

namespace {

// A force PDF is of |F_n|/<F_n>: a magnitude or a mean beyond the largest double has none.
[[noreturn]] void refuse_unbounded_force(const Eigen::ArrayXd& magnitude,
                                         const std::string& where) {
  // The first magnitude past the largest double, else the largest (a sum past it).
  Eigen::Index row = 0;
  while (row < magnitude.size() && std::isfinite(magnitude[row])) ++row;
  if (row == magnitude.size()) magnitude.maxCoeff(&row);
  throw InputError(where + ": contact " + std::to_string(row) +
                   ": expected normal forces whose mean is a finite number, got |F_n| = " +
                   format_number(magnitude[row]));
}

}  // namespace

ForceContacts force_contacts(const Frame& frame, const ForceSettings& settings,
                             const std::string& where) {
  if (!frame.contacts) {
    throw InputError(where +
                     ": expected a contact table with normal_force, got a frame "
                     "without contacts");
  }
  if (!frame.contacts->has("normal_force")) {
    throw InputError(where + ": expected the contact column normal_force, got contacts without it");
  }
  ForceContacts out;
  out.loaded = static_cast<long>(loaded_pair_contacts(frame, where).size());
  // stableNorm: the plain norm squares the components, and a force of 1e160 became
  // infinite, then every f = |F_n|/<F_n> NaN.
  out.magnitude =
      frame.contacts->get<Coordinates>("normal_force").matrix().rowwise().stableNorm().array();
  if (!out.magnitude.allFinite()) refuse_unbounded_force(out.magnitude, where);
  const IndexArray& j = frame.contact_j();
  double sum = 0.0;
  for (Eigen::Index row = 0; row < j.size(); ++row) {
    if (!(out.magnitude[row] > settings.min_force)) continue;
    const bool pair = partner::is_particle(j[row]);
    if (pair) out.edges.push_back(row);
    if (pair || (settings.walls && partner::is_wall(j[row]))) {
      out.samples.push_back(row);
      sum += out.magnitude[row];
    }
  }
  if (!out.samples.empty()) out.mean = sum / static_cast<double>(out.samples.size());
  if (!std::isfinite(sum)) refuse_unbounded_force(out.magnitude, where);
  return out;
}

std::vector<double> scaled_forces(const ForceContacts& forces,
                                  const std::vector<Eigen::Index>& rows, double mean) {
  std::vector<double> f;
  f.reserve(rows.size());
  for (Eigen::Index row : rows) f.push_back(mean > 0.0 ? forces.magnitude[row] / mean : 0.0);
  return f;
}

Coordinates contact_points(const Frame& frame, const std::vector<Eigen::Index>& rows,
                           const std::string& where) {
  if (!frame.contacts->has("point")) {
    throw InputError(where + ": expected the contact column point, got contacts without it");
  }
  const Coordinates& point = frame.contacts->get<Coordinates>("point");
  Coordinates out(static_cast<Eigen::Index>(rows.size()), point.cols());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (!point.row(rows[k]).allFinite()) {
      throw InputError(where + ": contact " + std::to_string(rows[k]) +
                       ": expected a finite contact point, got a NaN or infinite coordinate");
    }
    out.row(static_cast<Eigen::Index>(k)) = point.row(rows[k]);
  }
  return out;
}

}  // namespace granpipe::force_network
