#pragma once
// The multipass MST of the paper's Sec. III.C: pass 1 is the minimum spanning forest of
// the candidate graph; before each later pass, every edge selected for the first time by
// the pass before is lengthened once by the elongation factor (an edge selected in several
// passes is lengthened once, not once per pass), and the forest is computed again.
//
// Kruskal over edges kept sorted by (weight, i, j), with Boost's disjoint sets; ties by
// (i, j) so that equal lengths (lattices) give one answer whatever the edges' order. The sorted
// order is made once; between passes only the newly lengthened edges move: they are taken
// out (still in order among themselves), lengthened and merged back in linear time.
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "edge.hpp"

namespace granpipe::mst {

class Multipass {
 public:
  // `vertices` particles 0..vertices-1; `edges` in any order, i < j < vertices. A run of
  // weights within `tie` of its first is a tie, (i, j) then deciding: lengths of
  // a lattice are equal but for the rounding of the coordinates they come from, which a
  // frame moved or stored at another periodic image changes. 0: equal weights only.
  Multipass(std::uint32_t vertices, std::vector<Edge> edges, double elongation, double tie = 0.0);

  struct Pass {
    double weight = 0.0;    // of the forest, with the lengthened weights
    std::size_t edges = 0;  // in the forest: vertices minus trees
    std::vector<std::pair<std::uint32_t, std::uint32_t>> new_edges;  // selected first now
  };
  // Computes the next pass.
  Pass next();

 private:
  struct Ranked {
    Edge edge;
    std::uint32_t first_pass;  // 0: never selected
  };
  static bool ranked_lighter(const Ranked& a, const Ranked& b) {
    return std::tie(a.edge.weight, a.edge.i, a.edge.j) <
           std::tie(b.edge.weight, b.edge.i, b.edge.j);
  }
  void lengthen_last_selection();
  // The edges of sorted_ from `first` whose weights chain within tie_, in (i, j) order.
  std::size_t tied_run(std::size_t first);

  std::uint32_t vertices_;
  double elongation_, tie_;
  int passes_ = 0;
  std::size_t forest_edges_ = 0;  // known after pass 1: the candidate graph's
  std::vector<Ranked> sorted_, kept_, lengthened_;
  std::vector<Ranked*> run_;  // tied_run's
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint8_t> rank_;
};

}  // namespace granpipe::mst
