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

// A sum with the rounding error of each addition carried along (Neumaier's variant of
// Kahan's): what it loses is about one rounding of the total, whatever the count.
class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    lost_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + lost_; }

 private:
  double sum_ = 0.0, lost_ = 0.0;
};

// The mean of the rows' magnitudes, correctly rounded but in rare cases: a compensated sum,
// then the same of the deviations from it. Contacts are strong when above the mean, so ties
// must stay ties: with a plain sum, 300 contacts of |F_n| = 0.3 had the mean
// 0.2999999999999983 and were all strong.
double mean_magnitude(const Eigen::ArrayXd& magnitude, const std::vector<Eigen::Index>& rows) {
  const auto n = static_cast<double>(rows.size());
  CompensatedSum sum;
  for (Eigen::Index row : rows) sum.add(magnitude[row]);
  const double first = sum.value() / n;
  if (!std::isfinite(first)) return first;
  CompensatedSum deviation;
  for (Eigen::Index row : rows) deviation.add(magnitude[row] - first);
  return first + deviation.value() / n;
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
  for (Eigen::Index row = 0; row < j.size(); ++row) {
    if (!(out.magnitude[row] > settings.min_force)) continue;
    const bool pair = partner::is_particle(j[row]);
    if (pair) out.edges.push_back(row);
    if (pair || (settings.walls && partner::is_wall(j[row]))) out.samples.push_back(row);
  }
  if (out.samples.empty()) return out;
  out.mean = mean_magnitude(out.magnitude, out.samples);
  if (!std::isfinite(out.mean)) refuse_unbounded_force(out.magnitude, where);
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
