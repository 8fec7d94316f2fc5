#include "contact_pairs.hpp"

#include <algorithm>

#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/loaded_pair_contacts.hpp"
#include "granpipe/separation.hpp"

namespace granpipe::mst {

namespace {

// Every row of the table that joins two particles.
std::vector<Eigen::Index> pair_rows(const Frame& f) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index k = 0; k < f.contact_j().size(); ++k) {
    if (partner::is_particle(f.contact_j()[k])) rows.push_back(k);
  }
  return rows;
}

ContactPairs::Pair ordered(std::int64_t a, std::int64_t b) {
  return {std::min(a, b), std::max(a, b)};
}

// The pairs of the table rows `counted` (ascending).
ContactPairs from_table(const Frame& f, const std::vector<Eigen::Index>& counted) {
  ContactPairs c;
  c.from_table = true;
  for (Eigen::Index row : counted)
    c.pairs.push_back(ordered(f.contact_i()[row], f.contact_j()[row]));
  std::sort(c.pairs.begin(), c.pairs.end());
  c.pairs.erase(std::unique(c.pairs.begin(), c.pairs.end()), c.pairs.end());
  c.pair_of_row.assign(static_cast<std::size_t>(f.contacts->rows()), -1);
  for (Eigen::Index row : counted) {
    const auto [i, j] = ordered(f.contact_i()[row], f.contact_j()[row]);
    c.pair_of_row[static_cast<std::size_t>(row)] = c.find(i, j);
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

ContactPairs contact_pairs(const Frame& frame, FrameCache& cache, const ContactRule& rule,
                           const std::string& where) {
  const std::vector<Eigen::Index> loaded = loaded_pair_contacts(frame, where);
  ContactPairs c = !frame.contacts            ? by_distance(frame, cache, rule.tolerance)
                   : rule.zero_force_contacts ? from_table(frame, pair_rows(frame))
                                              : from_table(frame, loaded);
  c.loaded = static_cast<std::int64_t>(loaded.size());
  c.length.reserve(c.pairs.size());
  for (const auto& [i, j] : c.pairs) c.length.push_back(separation(frame, i, j).norm());
  return c;
}

}  // namespace granpipe::mst
