#include "candidate_edges.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "granpipe/cell_list.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe::mst {

namespace {

void check_particle_count(const Frame& frame, const std::string& where) {
  if (static_cast<std::uint64_t>(frame.size()) >= std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(where + ": expected fewer than 2^32 particles for the MST, got " +
                     std::to_string(frame.size()));
  }
}

// More candidate pairs per particle than any useful cutoff gives (a cutoff of 3, where the
// automatic one stops, gives some 70 in a dense packing): a cutoff far too large made the
// candidate graph nearly complete, and the run ran out of memory (std::bad_alloc, exit 1).
constexpr double kMaxCandidatesPerParticle = 500;

[[noreturn]] void refuse_candidate_count(const Frame& frame, double most, double factor,
                                         const std::string& where) {
  throw InputError(where + ": cutoff: expected at most " +
                   format_number(kMaxCandidatesPerParticle) + " candidate pairs per particle (" +
                   format_number(most) + " for " + std::to_string(frame.size()) +
                   " particles), got more with cutoff " + format_number(factor) +
                   " (the automatic cutoff, 0, stops at 3)");
}

}  // namespace

std::vector<Edge> cutoff_edges(const Frame& frame, double factor, const std::string& where) {
  std::vector<Edge> edges;
  if (frame.size() < 2) return edges;
  const Eigen::ArrayXd& r = frame.radius();
  const CellList cells(frame.position(), frame.container, frame.dim, 2.0 * factor * r.maxCoeff(),
                       where);
  const double most = kMaxCandidatesPerParticle * static_cast<double>(frame.size());
  cells.for_each_pair([&](int i, int j, const double*, double r2) {
    const double reach = factor * (r[i] + r[j]);
    if (r2 < reach * reach) {
      if (static_cast<double>(edges.size()) >= most)
        refuse_candidate_count(frame, most, factor, where);
      edges.push_back(
          {std::sqrt(r2), static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
    }
  });
  return edges;
}

std::vector<Edge> candidate_edges(const Frame& frame, Candidates kind, double cutoff_factor,
                                  const std::string& where) {
  check_particle_count(frame, where);
  if (kind == Candidates::Delaunay) return delaunay_edges(frame, where);
  return cutoff_edges(frame, cutoff_factor, where);
}

}  // namespace granpipe::mst
