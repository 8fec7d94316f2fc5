#pragma once
// The candidate graph the MST is computed on: edges between nearby particles only, so that
// the MST costs O(N log N) instead of O(N^2). docs/mst.md says when the result equals the
// MST of the complete graph.
#include <string>
#include <vector>

#include "edge.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/params.hpp"

namespace granpipe::mst {

enum class Candidates { Delaunay, Cutoff };
inline ChoiceNames<Candidates> choice_names(Candidates) {
  return {{"delaunay", Candidates::Delaunay}, {"cutoff", Candidates::Cutoff}};
}

// Every pair with |r_ij| < factor (R_i + R_j) (minimum image along periodic sides), with
// rows as particle numbers. InputError after `where` when the box is too small for the
// cutoff (see CellList).
std::vector<Edge> cutoff_edges(const Frame& frame, double factor, const std::string& where);

// The edges of the Delaunay triangulation of the centres (2D or 3D), which contains the
// Euclidean MST; particles at one position are joined by an edge of weight 0. InputError
// after `where` for a container with a periodic side (the triangulation has no images).
std::vector<Edge> delaunay_edges(const Frame& frame, const std::string& where);

// One of the two; InputError after `where` also for 2^32 particles or more.
std::vector<Edge> candidate_edges(const Frame& frame, Candidates kind, double cutoff_factor,
                                  const std::string& where);

}  // namespace granpipe::mst
