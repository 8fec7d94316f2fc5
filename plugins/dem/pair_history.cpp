#include "pair_history.hpp"

#include <algorithm>

namespace granpipe::dem {

namespace {

bool is_zero(const double* u) { return u[0] == 0.0 && u[1] == 0.0 && u[2] == 0.0; }

}  // namespace

void PairHistory::save(std::span<const std::int32_t> first, std::span<const std::int32_t> partner,
                       std::span<const double> history, const std::vector<std::int32_t>& tag) {
  const std::size_t n = tag.size();
  start_.assign(n + 1, 0);
  if (first.size() != n + 1) return;  // no list yet
  for (std::size_t i = 0; i < n; ++i) {
    for (std::int32_t k = first[i]; k < first[i + 1]; ++k) {
      if (is_zero(&history[3 * k])) continue;
      ++start_[std::min(tag[i], tag[partner[k]]) + 1];
    }
  }
  for (std::size_t t = 0; t < n; ++t) start_[t + 1] += start_[t];
  entries_.resize(static_cast<std::size_t>(start_[n]));
  std::vector<std::int32_t>& fill = start_;  // advanced while filling, restored below
  for (std::size_t i = 0; i < n; ++i) {
    for (std::int32_t k = first[i]; k < first[i + 1]; ++k) {
      const double* u = &history[3 * k];
      if (is_zero(u)) continue;
      const std::int32_t a = tag[i], b = tag[partner[k]];
      const double sign = a < b ? 1.0 : -1.0;
      Entry& e = entries_[static_cast<std::size_t>(fill[std::min(a, b)]++)];
      e.other = std::max(a, b);
      for (int c = 0; c < 3; ++c) e.u[c] = sign * u[c];
    }
  }
  // Each start_[t] now holds the end of t's list, which is the start of t + 1's.
  for (std::size_t t = n; t > 0; --t) start_[t] = start_[t - 1];
  start_[0] = 0;
}

void PairHistory::find(std::int32_t tag_i, std::int32_t tag_j, double* u) const {
  const std::int32_t owner = std::min(tag_i, tag_j), other = std::max(tag_i, tag_j);
  u[0] = u[1] = u[2] = 0.0;
  if (static_cast<std::size_t>(owner) + 1 >= start_.size()) return;
  for (std::int32_t k = start_[owner]; k < start_[owner + 1]; ++k) {
    const Entry& e = entries_[static_cast<std::size_t>(k)];
    if (e.other != other) continue;
    const double sign = owner == tag_i ? 1.0 : -1.0;
    for (int c = 0; c < 3; ++c) u[c] = sign * e.u[c];
    return;
  }
}

}  // namespace granpipe::dem
