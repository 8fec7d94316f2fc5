#include <string>
#include <vector>

#include "granpipe/params.hpp"

namespace granpipe {

std::optional<std::size_t> SpeciesTable::find(const std::string& name) const {
  for (std::size_t i = 0; i < species_.size(); ++i)
    if (this->name(i) == name) return i;
  return std::nullopt;
}

std::vector<double> SpeciesTable::reals(const std::string& field) const {
  std::vector<double> values;
  values.reserve(species_.size());
  for (const Params& s : species_) values.push_back(s.real(field));
  return values;
}

namespace {
// Place of pair (i, j), i <= j, in the upper triangle stored row by row.
std::size_t triangle_index(std::size_t i, std::size_t j, std::size_t n) {
  return i * n - i * (i - 1) / 2 + (j - i);
}
}  // namespace

PairTable::PairTable(std::vector<std::string> species, std::vector<Params> pairs)
    : species_(std::move(species)), pairs_(std::move(pairs)) {
  const std::size_t n = species_.size();
  if (pairs_.size() != n * (n + 1) / 2) {
    throw InternalError("a pair table of " + std::to_string(n) + " species holds " +
                        std::to_string(pairs_.size()) + " pairs");
  }
}

const Params& PairTable::at(std::size_t i, std::size_t j) const {
  if (i > j) std::swap(i, j);
  if (j >= species_.size()) {
    throw InternalError("pair (" + std::to_string(i) + ", " + std::to_string(j) +
                        ") of a table of " + std::to_string(species_.size()) + " species");
  }
  return pairs_[triangle_index(i, j, species_.size())];
}

std::string PairTable::key(std::size_t i, std::size_t j) const {
  if (i > j) std::swap(i, j);
  return species_.at(i) + "-" + species_.at(j);
}

PairMatrix PairTable::matrix(const std::string& field) const {
  const std::size_t n = species_.size();
  std::vector<double> values(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) values[i * n + j] = at(i, j).real(field);
  return {n, std::move(values)};
}

}  // namespace granpipe
