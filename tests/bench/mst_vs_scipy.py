"""The multipass MST (5 passes) on one candidate graph: granpipe's (bench_mst) against
scipy.sparse.csgraph.minimum_spanning_tree, per pass (median of 3 runs), with the forest weights compared.

The graph is that of a dense packing's contact range: an FCC crystal of unit spacing with
each centre moved uniformly within a ball of radius 0.06, joined by its ~4.5 N shortest
pairs, handed to both in random order (as unsorted as a cell list's). scipy runs the same
multipass (edges first selected by a pass lengthened once by 1.2 before the next), so that
both compute the same forests.

    /usr/bin/python3 tests/bench/mst_vs_scipy.py build [particles ...]
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import minimum_spanning_tree
from scipy.spatial import cKDTree

PASSES, ELONGATION, EDGES_PER_PARTICLE, REPEATS = 5, 1.2, 4.5, 3


def packing(particles, rng):
    cells = round((particles / 4) ** (1 / 3))
    base = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]]) * np.sqrt(2)
    grid = np.stack(np.meshgrid(*[np.arange(cells)] * 3, indexing="ij"), -1).reshape(-1, 3) * np.sqrt(2)
    x = (grid[:, None, :] + base[None, :, :]).reshape(-1, 3)
    direction = rng.normal(size=x.shape)
    direction /= np.linalg.norm(direction, axis=1)[:, None]
    radius = 0.06 * rng.uniform(size=(len(x), 1)) ** (1 / 3)
    return x + direction * radius


def candidate_graph(x, rng):
    """The ~4.5 N shortest pairs, in random order: a frame's candidates come from a cell
    list, unsorted by length, and pass 1 sorts them; edges handed over already sorted
    would leave that sort almost nothing to do."""
    pairs = cKDTree(x).query_pairs(1.2, output_type="ndarray")
    length = np.linalg.norm(x[pairs[:, 0]] - x[pairs[:, 1]], axis=1)
    keep = np.argsort(length, kind="stable")[: int(EDGES_PER_PARTICLE * len(x))]
    keep = rng.permutation(keep)
    i, j = np.minimum(pairs[keep, 0], pairs[keep, 1]), np.maximum(pairs[keep, 0], pairs[keep, 1])
    return i.astype(np.uint32), j.astype(np.uint32), length[keep]


def scipy_multipass(n, i, j, w):
    """Seconds of minimum_spanning_tree (the sparse matrix is made outside) and forest
    weight, per pass."""
    key = i.astype(np.int64) * n + j
    order = np.argsort(key)
    weight, first = w.copy(), np.zeros(len(w), dtype=np.int32)
    out = []
    for p in range(1, PASSES + 1):
        graph = csr_matrix((weight, (i, j)), shape=(n, n))  # not timed: scipy's input
        t0 = time.perf_counter()
        tree = minimum_spanning_tree(graph).tocoo()
        seconds = time.perf_counter() - t0
        out.append((seconds, tree.data.sum()))
        a, b = np.minimum(tree.row, tree.col), np.maximum(tree.row, tree.col)
        picked = order[np.searchsorted(key[order], a.astype(np.int64) * n + b)]
        new = picked[first[picked] == 0]
        first[new] = p
        weight[new] *= ELONGATION
    return out


def granpipe_multipass(build, n, i, j, w):
    with tempfile.NamedTemporaryFile(suffix=".edges", delete=False) as f:
        f.write(np.array([n, len(w)], dtype="<u8").tobytes())
        rows = np.empty(len(w), dtype=[("i", "<u4"), ("j", "<u4"), ("w", "<f8")])
        rows["i"], rows["j"], rows["w"] = i, j, w
        f.write(rows.tobytes())
        path = f.name
    try:
        run = subprocess.run([f"{build}/bin/bench_mst", path, str(PASSES), str(ELONGATION)],
                             check=True, capture_output=True, text=True)
    finally:
        os.unlink(path)
    return [(float(s), float(wt)) for _, s, wt, _ in (line.split() for line in run.stdout.splitlines())]


def median_of_runs(run):
    """Per pass, the median seconds of REPEATS runs (a shared machine's load comes and
    goes) and the forest weight (the same in every run)."""
    runs = [run() for _ in range(REPEATS)]
    return [(float(np.median([r[p][0] for r in runs])), runs[0][p][1]) for p in range(len(runs[0]))]


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    sizes = [int(float(a)) for a in sys.argv[2:]] or [100_000, 1_000_000]
    rng = np.random.default_rng(1)
    print(f"{'N':>9} {'edges':>9} {'pass':>4} {'granpipe s':>10} {'scipy s':>9} {'scipy/granpipe':>14} {'weights equal':>13}")
    for particles in sizes:
        x = packing(particles, rng)
        i, j, w = candidate_graph(x, rng)
        ours = median_of_runs(lambda: granpipe_multipass(build, len(x), i, j, w))
        theirs = median_of_runs(lambda: scipy_multipass(len(x), i, j, w))
        for p, ((s_ours, w_ours), (s_scipy, w_scipy)) in enumerate(zip(ours, theirs), 1):
            equal = abs(w_ours - w_scipy) <= 1e-9 * w_scipy
            print(f"{len(x):>9} {len(w):>9} {p:>4} {s_ours:>10.3f} {s_scipy:>9.3f} "
                  f"{s_scipy / s_ours:>14.2f} {str(equal):>13}")


if __name__ == "__main__":
    main()
