#include "tcp_report.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "granpipe/coordinate_spacing.hpp"
#include "multipass.hpp"

namespace granpipe::mst {

namespace {

// Particles numbered in order of their ids (then rows), so that ties between equal
// lengths are broken by the particles' ids, not by the order a file lists them in.
std::vector<std::uint32_t> rows_by_id(const Frame& f) {
  std::vector<std::uint32_t> rows(static_cast<std::size_t>(f.size()));
  std::iota(rows.begin(), rows.end(), 0u);
  std::stable_sort(rows.begin(), rows.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return f.id()[a] < f.id()[b]; });
  return rows;
}

std::vector<Edge> renumbered(std::vector<Edge> edges,
                             const std::vector<std::uint32_t>& number_of_row) {
  for (Edge& e : edges) {
    const std::uint32_t a = number_of_row[e.i], b = number_of_row[e.j];
    e.i = std::min(a, b);
    e.j = std::max(a, b);
  }
  return edges;
}

// Below which length every pair is a candidate: cutoff x (2 R_min) for "cutoff"; for
// "delaunay", sqrt(2) x the shortest centre distance (such a pair's diametral sphere holds
// no other centre, so the pair is a Delaunay edge).
double complete_below(const Frame& f, const MstOptions& o, double cutoff,
                      const std::vector<Edge>& edges) {
  if (f.size() < 2) return 0.0;
  if (o.candidates == Candidates::Cutoff) return cutoff * 2.0 * f.radius().minCoeff();
  double shortest = INFINITY;
  for (const Edge& e : edges) shortest = std::min(shortest, e.weight);
  return std::sqrt(2.0) * shortest;
}

// The largest weight a contact reaches: lengthened once when there is a second pass.
double stretch(const MstOptions& o) { return o.passes > 1 ? o.elongation : 1.0; }

// The smallest cutoff under which every contact is proven (a little above, since the
// candidates are the pairs strictly below), at least 1 and at most kMaxAutoCutoff, so that a
// few very large particles cannot make the candidate graph (nearly) complete.
constexpr double kMaxAutoCutoff = 3.0;
double auto_cutoff(const Frame& f, const MstOptions& o, const ContactPairs& c) {
  if (f.size() < 2 || c.length.empty()) return 1.0;
  const double longest = *std::max_element(c.length.begin(), c.length.end());
  const double needed = stretch(o) * longest / (2.0 * f.radius().minCoeff()) * (1.0 + 1e-9);
  return std::clamp(needed, 1.0, kMaxAutoCutoff);
}

std::int64_t unproven(const MstOptions& o, const TcpReport& r) {
  if (o.candidates == Candidates::Delaunay && o.passes == 1) return 0;  // the EMST itself
  return std::count_if(r.pairs.length.begin(), r.pairs.length.end(),
                       [&](double l) { return !(stretch(o) * l < r.complete_below); });
}

// How far apart two lengths may be and still tie: 64 units in the last place of the largest
// coordinate (or periodic box side), above the rounding of a centre distance computed from such
// coordinates (a few units) and below any difference of lengths that is not rounding near
// the origin. Without it an SC lattice moved by 0.1 selected 248 contacts in pass 2 instead
// of 239. Far enough out it reaches the lengths themselves (a whole diameter at 1e14, every
// length tied, pass 2 selecting nothing): refused there.
double tie_length(const Frame& f, const std::string& where) {
  constexpr double kTieSpacings = 64.0;
  double largest = largest_coordinate(f);
  // A periodic side's bounds enter the images' lengths; a wall's enter none.
  for (int a = 0; a < f.dim; ++a) {
    if (!f.container.periodic(a)) continue;
    largest = std::max({largest, std::abs(f.container.lo[a]), std::abs(f.container.hi[a])});
  }
  if (f.size() > 0) {
    require_fine_positions(largest, kTieSpacings, 2.0 * f.radius().minCoeff(),
                           "smallest contact distance", where);
  }
  return kTieSpacings * double_spacing(largest);
}

}  // namespace

TcpReport tcp_report(const Frame& frame, FrameCache& cache, const MstOptions& options,
                     const std::string& where) {
  TcpReport r;
  const auto n = static_cast<std::uint32_t>(frame.size());
  r.pairs = contact_pairs(frame, cache, options.contacts, where);
  r.contacts = static_cast<std::int64_t>(r.pairs.pairs.size());
  r.network = components(n, r.pairs.pairs).counts;
  r.first_pass.assign(r.pairs.pairs.size(), 0);

  r.cutoff = options.cutoff > 0.0 ? options.cutoff : auto_cutoff(frame, options, r.pairs);
  std::vector<Edge> edges = candidate_edges(frame, options.candidates, r.cutoff, where);
  r.complete_below = complete_below(frame, options, r.cutoff, edges);
  r.unproven = unproven(options, r);

  const std::vector<std::uint32_t> row_of = rows_by_id(frame);
  std::vector<std::uint32_t> number_of_row(row_of.size());
  for (std::uint32_t k = 0; k < n; ++k) number_of_row[row_of[k]] = k;
  Multipass mst(n, renumbered(std::move(edges), number_of_row), options.elongation,
                tie_length(frame, where));

  std::vector<ContactPairs::Pair> selected;  // contacting edges selected so far, as rows
  for (int p = 1; p <= options.passes; ++p) {
    for (const auto& [a, b] : mst.next().new_edges) {
      const std::int64_t k = r.pairs.find(row_of[a], row_of[b]);
      if (k < 0) continue;
      r.first_pass[static_cast<std::size_t>(k)] = p;
      selected.push_back(r.pairs.pairs[static_cast<std::size_t>(k)]);
    }
    Components tcps = components(n, selected);
    r.passes.push_back({p, tcps.counts, static_cast<std::int64_t>(selected.size())});
    if (p == options.passes) r.tcp = std::move(tcps.label);
  }
  return r;
}

}  // namespace granpipe::mst
