#include "contact_pairs.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/contacts_by_distance.hpp"

namespace granpipe::mst {

namespace {

// Rows of the table that count: particle partners, with a force unless zero forces count.
std::vector<bool> counted_rows(const Frame& f, bool zero_force_contacts) {
  const PropertyTable& table = *f.contacts;
  std::vector<bool> counted(static_cast<std::size_t>(table.rows()));
  const ValueTable<double>* force = !zero_force_contacts && table.has("normal_force")
                                        ? &table.get<ValueTable<double>>("normal_force")
                                        : nullptr;
  for (Eigen::Index k = 0; k < table.rows(); ++k) {
    bool c = partner::is_particle(f.contact_j()[k]) && f.contact_i()[k] != f.contact_j()[k];
    if (c && force) c = (force->row(k) != 0.0).any();
    counted[static_cast<std::size_t>(k)] = c;
  }
  return counted;
}

ContactPairs::Pair ordered(std::int64_t a, std::int64_t b) {
  return {std::min(a, b), std::max(a, b)};
}

double centre_distance(const Frame& f, std::int64_t a, std::int64_t b) {
  double r2 = 0.0;
  for (int axis = 0; axis < f.dim; ++axis) {
    const double d = f.container.minimum_image(axis, f.position()(b, axis) - f.position()(a, axis));
    r2 += d * d;
  }
  return std::sqrt(r2);
}

ContactPairs from_table(const Frame& f, bool zero_force_contacts) {
  ContactPairs c;
  c.from_table = true;
  const std::vector<bool> counted = counted_rows(f, zero_force_contacts);
  for (std::size_t k = 0; k < counted.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    if (counted[k]) c.pairs.push_back(ordered(f.contact_i()[row], f.contact_j()[row]));
  }
  std::sort(c.pairs.begin(), c.pairs.end());
  c.pairs.erase(std::unique(c.pairs.begin(), c.pairs.end()), c.pairs.end());
  c.pair_of_row.assign(counted.size(), -1);
  for (std::size_t k = 0; k < counted.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    if (!counted[k]) continue;
    const auto [i, j] = ordered(f.contact_i()[row], f.contact_j()[row]);
    c.pair_of_row[k] = c.find(i, j);
  }
  return c;
}

ContactPairs by_distance(const Frame& f, FrameCache& cache, double tolerance) {
  ContactPairs c;
  const DistanceContacts& d = contacts_by_distance(f, cache, tolerance);
  for (Eigen::Index k = 0; k < d.pairs; ++k) c.pairs.push_back(ordered(d.i[k], d.j[k]));
  return c;  // already sorted, i < j
}

}  // namespace

std::int64_t ContactPairs::find(std::int64_t i, std::int64_t j) const {
  const Pair p{std::min(i, j), std::max(i, j)};
  const auto it = std::lower_bound(pairs.begin(), pairs.end(), p);
  return it != pairs.end() && *it == p ? it - pairs.begin() : -1;
}

ContactPairs contact_pairs(const Frame& frame, FrameCache& cache, const ContactRule& rule) {
  ContactPairs c = frame.contacts ? from_table(frame, rule.zero_force_contacts)
                                  : by_distance(frame, cache, rule.tolerance);
  c.length.reserve(c.pairs.size());
  for (const auto& [i, j] : c.pairs) c.length.push_back(centre_distance(frame, i, j));
  return c;
}

std::int64_t loaded_contacts(const Frame& frame, FrameCache& cache, double tolerance) {
  if (!frame.contacts) return contacts_by_distance(frame, cache, tolerance).pairs;
  const std::vector<bool> counted = counted_rows(frame, false);
  return std::count(counted.begin(), counted.end(), true);
}

}  // namespace granpipe::mst
