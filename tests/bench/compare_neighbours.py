"""Neighbour pairs within a cutoff in a periodic 3D box: granpipe's cell list against
scipy's cKDTree (query_pairs with boxsize), side by side in one run so that the ratio
holds on a noisy machine. Both build their search structure and return the list of pairs;
both draw uniform random points at the same density (not the same points), and both pair
counts are checked against the expected N(N-1)/2 * 4/3 pi rc^3 / V.

    apt-get install python3-scipy
    /usr/bin/python3 tests/bench/compare_neighbours.py build
"""
import json
import math
import subprocess
import sys
import time

import numpy as np
from scipy.spatial import cKDTree

build = sys.argv[1] if len(sys.argv) > 1 else "build"
density, cutoff, repeats = 1.1, 1.0, 5  # as in bench_cell_list.cpp
print(f"{'N':>7} {'granpipe ms':>12} {'scipy ms':>10} {'scipy/granpipe':>15} {'pairs granpipe':>15} {'pairs scipy':>12} {'expected':>10}")
for n in (8000, 64000):
    run = subprocess.run([f"{build}/bin/bench_cell_list", f"--benchmark_filter=BM_CellListPairs/3/{n}$",
                          "--benchmark_format=json", f"--benchmark_repetitions={repeats}",
                          "--benchmark_report_aggregates_only=true"],
                         check=True, capture_output=True, text=True)
    stats = {b["aggregate_name"]: b for b in json.loads(run.stdout)["benchmarks"] if "aggregate_name" in b}
    ours_ms = stats["median"]["real_time"]
    ours_pairs = stats["median"]["pairs"]

    side = (n / density) ** (1 / 3)
    x = np.random.default_rng(1).uniform(0, side, size=(n, 3))
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        pairs = cKDTree(x, boxsize=side).query_pairs(cutoff, output_type="ndarray")
        times.append(1e3 * (time.perf_counter() - t0))
    scipy_ms = float(np.median(times))
    expected = n * (n - 1) / 2 * (4 / 3 * math.pi * cutoff**3) / side**3
    print(f"{n:>7} {ours_ms:>12.2f} {scipy_ms:>10.2f} {scipy_ms / ours_ms:>15.2f} {ours_pairs:>15.0f} {len(pairs):>12} {expected:>10.0f}")
