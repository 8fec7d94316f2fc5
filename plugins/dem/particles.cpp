#include "particles.hpp"

#include "granpipe/huge_pages.hpp"

namespace granpipe::dem {

namespace {

template <class A>
void advise(A& a) {
  huge_pages::advise(a.data(), static_cast<std::size_t>(a.size()) * sizeof(*a.data()));
}

}  // namespace

void Particles::prefer_huge_pages() {
  for (Vectors* a : {&x, &v, &omega, &force, &torque}) advise(*a);
  for (Vectors& h : wall_history) advise(h);
  for (Vectors& h : wall_rolling_history) advise(h);
  advise(radius);
  advise(inv_mass);
  advise(inv_inertia);
  advise(species);
  advise(tag);
}

void Particles::permute(const std::vector<std::int32_t>& order) {
  const Eigen::Index n = size();
  if (scratch_vectors_.cols() != n) {
    scratch_vectors_.resize(3, n);
    scratch_reals_.resize(n);
    scratch_ints_.resize(n);
    scratch_tags_.resize(static_cast<std::size_t>(n));
    advise(scratch_vectors_);
    advise(scratch_reals_);
    advise(scratch_ints_);
    advise(scratch_tags_);
  }
  const auto vectors = [&](Vectors& a) {
    if (a.cols() != n) return;  // an unused quantity (e.g. no wall history)
    for (Eigen::Index k = 0; k < n; ++k) scratch_vectors_.col(k) = a.col(order[k]);
    a.swap(scratch_vectors_);
  };
  const auto reals = [&](Eigen::ArrayXd& a) {
    for (Eigen::Index k = 0; k < n; ++k) scratch_reals_[k] = a[order[k]];
    a.swap(scratch_reals_);
  };
  vectors(x);
  vectors(v);
  vectors(omega);
  vectors(force);
  vectors(torque);
  for (Vectors& h : wall_history) vectors(h);
  for (Vectors& h : wall_rolling_history) vectors(h);
  reals(radius);
  reals(inv_mass);
  reals(inv_inertia);
  for (Eigen::Index k = 0; k < n; ++k) scratch_ints_[k] = species[order[k]];
  species.swap(scratch_ints_);
  for (Eigen::Index k = 0; k < n; ++k) scratch_tags_[k] = tag[order[k]];
  tag.swap(scratch_tags_);
}

}  // namespace granpipe::dem
