// The multipass MST on a given candidate graph, timed per pass: a plain timing binary that
// tests/bench/mst_vs_scipy.py runs on the edges it also gives scipy.
//
//   bench_mst EDGES [PASSES] [ELONGATION]
//
// EDGES is binary: uint64 particles, uint64 edges, then per edge uint32 i, uint32 j,
// float64 length (little endian). Prints one line per pass: pass, seconds, forest weight,
// forest edges. Pass 1 includes sorting the edges.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "multipass.hpp"

using granpipe::mst::Edge;
using granpipe::mst::Multipass;

namespace {

struct Graph {
  std::uint64_t particles = 0;
  std::vector<Edge> edges;
};

bool read_graph(const char* path, Graph& g) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t m = 0;
  if (!in.read(reinterpret_cast<char*>(&g.particles), 8) ||
      !in.read(reinterpret_cast<char*>(&m), 8))
    return false;
  g.edges.resize(m);
  for (Edge& e : g.edges) {
    if (!in.read(reinterpret_cast<char*>(&e.i), 4) || !in.read(reinterpret_cast<char*>(&e.j), 4) ||
        !in.read(reinterpret_cast<char*>(&e.weight), 8))
      return false;
    if (e.i > e.j) std::swap(e.i, e.j);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Graph g;
  if (argc < 2 || !read_graph(argv[1], g)) {
    std::fprintf(
        stderr,
        "usage: bench_mst EDGES [PASSES] [ELONGATION]: expected a readable edge file, got %s\n",
        argc < 2 ? "none" : argv[1]);
    return 2;
  }
  const int passes = argc > 2 ? std::stoi(argv[2]) : 5;
  const double elongation = argc > 3 ? std::stod(argv[3]) : 1.2;
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  Multipass mst(static_cast<std::uint32_t>(g.particles), std::move(g.edges), elongation);
  for (int p = 1; p <= passes; ++p) {
    const Multipass::Pass pass = mst.next();
    const auto end = Clock::now();
    std::printf("%d %.6f %.17g %zu\n", p, std::chrono::duration<double>(end - start).count(),
                pass.weight, pass.edges);
    start = Clock::now();
  }
  return 0;
}
