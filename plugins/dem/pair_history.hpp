#pragma once
// A contact history (the tangential displacement, or the rolling angle: a 3-vector that
// changes sign with the pair's order) kept across neighbour-list rebuilds, keyed by
// particle pair.
//
// Before a rebuild, every pair with a non-zero tangential displacement u is filed under the
// smaller tag of its two particles (a per-tag list, compressed rows: counting, prefix sum,
// fill), with u as seen from that particle. After the rebuild each new pair looks itself
// up in its smaller tag's short list. This is how LAMMPS' fix neigh/history carries shear
// history through reneighbouring (per-atom partner lists), without its per-atom pages: the
// arrays here grow to the largest size seen and are then reused, so a rebuild allocates
// nothing in a steady run.
#include <cstdint>
#include <span>
#include <vector>

namespace granpipe::dem {

class PairHistory {
 public:
  // Files the non-zero histories of the half list (first, partner) over particles with
  // these tags; history holds 3 doubles per pair, u of the pair's first particle.
  void save(std::span<const std::int32_t> first, std::span<const std::int32_t> partner,
            std::span<const double> history, const std::vector<std::int32_t>& tag);
  // Writes into u (3 doubles) the saved displacement of particle tag_i against tag_j (as
  // seen from tag_i), or zeros when the pair had none.
  void find(std::int32_t tag_i, std::int32_t tag_j, double* u) const;

 private:
  struct Entry {
    std::int32_t other;
    double u[3];
  };
  std::vector<std::int32_t> start_;  // tags + 1
  std::vector<Entry> entries_;
};

}  // namespace granpipe::dem
