#pragma once
// Verlet half list on a cell grid: every pair closer than R_i + R_j + skin is listed once,
// under one of its two particles (its "owner"), and rebuilt when a particle has moved more
// than skin/2 since the last build.
//
// A rebuild sorts the particles by cell (z-major), so that neighbours in space are
// neighbours in memory, then lists pairs in two parallel passes (count per owner, then
// fill), which gives the same list for any thread count. Cells are sized for the pairs of
// "small" particles (radius up to 1.5 x the median); a small particle lists the small
// particles after it in its own cell and in the 13 forward neighbour cells, and each "big"
// particle (a Brazil-nut intruder) searches every cell within its own reach for all its
// partners, so one large sphere does not inflate the cells of the whole bed.
//
// Per pair the list keeps the tangential displacement (history, 3 doubles, with friction),
// the rolling angle (rolling_history, 3 doubles, with rolling resistance)
// and a reaction slot the force loop writes (force on the partner, and n x F_t). The slots
// are laid out by partner, in increasing pair order per partner, so that each particle
// gathers its reactions in a fixed order from one contiguous run of memory, with no
// atomics, no per-thread copies and no index to follow.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "granpipe/huge_pages.hpp"
#include "pair_history.hpp"
#include "particles.hpp"

namespace granpipe::dem {

class NeighborList {
 public:
  // skin: the list's distance margin; reaction_stride: doubles per reaction slot (3
  // without rotation, 6 with: n x F_t too); history: whether pairs keep a tangential
  // displacement; rolling_history: whether they keep a rolling angle.
  NeighborList() = default;
  NeighborList(double skin, int reaction_stride, bool history, bool rolling_history);

  // Sorts `p` spatially, rebuilds the list and carries the pair histories over.
  void rebuild(Particles& p, int threads);
  // The largest squared displacement since the last rebuild that is still safe.
  double trigger_squared() const { return 0.25 * skin_ * skin_; }
  const Vectors& positions_at_build() const { return x_build_; }

  double skin() const { return skin_; }
  int pairs() const { return static_cast<int>(partner.size()); }
  std::int64_t builds() const { return builds_; }

  // Pairs of owner i are first[i] .. first[i+1]-1; owner[k] is the particle that lists
  // pair k (the force loop runs over pairs, not owners).
  HugePageVector<std::int32_t> first, partner, owner;
  HugePageVector<double> history;          // 3 per pair
  HugePageVector<double> rolling_history;  // 3 per pair (empty without rolling resistance)
  // The force loop's estimated work for the particles before i (n+1 entries), counting
  // their own forces, their listed pairs and their pairs in contact at the build: the
  // loop gives each thread an equal share of it.
  HugePageVector<double> work_before;
  // The reactions particle p gathers are the slots reverse_first[p] .. reverse_first[p+1]-1
  // of `incoming` (reaction_stride doubles each), one per pair naming p as partner, in
  // increasing pair order; pair k writes slot reaction_slot[k]. The force loop writes the
  // slots of touching pairs only, and the gather reads its slots and clears them (but on
  // the step a frame shows, whose contacts' forces are then read from the slots).
  HugePageVector<std::int32_t> reverse_first, reaction_slot;
  HugePageVector<double> incoming;
  int reaction_stride = 3;

 private:
  struct Grid {
    Eigen::Vector3d lo;
    double cell = 1.0, inv_cell = 1.0;
    int n[3] = {1, 1, 1};
    int cell_of(const double* x) const;
    int count() const { return n[0] * n[1] * n[2]; }
  };
  void size_grid(const Particles& p);
  void sort_by_cell(Particles& p);
  template <class F>
  void for_each_candidate(const Particles& p, int i, F&& f) const;
  void list_pairs(const Particles& p, int threads);
  // A saved history (tangential or rolling) put back on the new list's pairs.
  void restore_history(const PairHistory& saved, HugePageVector<double>& to, const Particles& p,
                       int threads);
  void index_reverse(int n);

  double skin_ = 0.0;
  bool keep_history_ = false, keep_rolling_history_ = false;
  double split_radius_ = 0.0, max_radius_ = 0.0;
  std::int64_t builds_ = 0;
  Grid grid_;
  std::vector<std::int32_t> cell_of_, cell_start_, order_, count_;
  std::vector<unsigned char> big_;
  Vectors x_build_;
  PairHistory saved_, saved_rolling_;
};

}  // namespace granpipe::dem
