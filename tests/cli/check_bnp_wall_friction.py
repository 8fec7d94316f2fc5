"""scripts/bnp_wall_friction.py reads the intruder's height once per cycle, at the phase of
compression: from frames that reach it, refusing a run that reaches none (a run to cycle
0.107 gave its last frame's height as cycle 0's, exit 0) and frames too far apart, with the
cycles the source counts (time x frequency ignored a drive's start).

usage: check_bnp_wall_friction.py SCRIPT"""
import json
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

script = sys.argv[1]
FREQUENCY, START = 0.107, 5.0
pipeline = {"source": {"params": {"drive": {"frequency": FREQUENCY, "start": START}}},
            "sweep": {"parameters": {"source.params.walls.mu": [0.1, 0.5]}}}


def results(folder, cycles):
    """A results.h5 of two sweep points whose intruder height is 10 x its frame's cycles,
    after 20 frames before the drive's start (cycles 0, height 0)."""
    cycles = np.concatenate([np.zeros(20), cycles])
    os.makedirs(folder)
    with h5py.File(os.path.join(folder, "results.h5"), "w") as f:
        f.attrs["pipeline"] = json.dumps(pipeline)
        for k in range(2):
            table = f.create_group(f"point_{k:03d}/intruder/per_frame")
            table["cycles"] = cycles
            table["time"] = np.concatenate([np.linspace(0, START, 20), START + cycles[20:] / FREQUENCY])
            table["intruder_height"] = 10.0 * cycles


failures = []
with tempfile.TemporaryDirectory() as work:
    short = os.path.join(work, "short")
    results(short, np.arange(0.0, 0.107, 0.01))
    r = subprocess.run([sys.executable, script, short], capture_output=True, text=True)
    expected = (f"{short}/results.h5: expected a run reaching the compression phase "
                "(0.28) of a cycle, found frames up to cycle 0.1\n")
    if r.returncode != 2 or r.stderr != expected:
        failures.append(f"a run short of its first compression: {r.returncode} {r.stderr!r}")
    sparse = os.path.join(work, "sparse")
    results(sparse, np.arange(0.0, 5.0, 1.07))
    r = subprocess.run([sys.executable, script, sparse], capture_output=True, text=True)
    expected = (f"{sparse}/results.h5: the point of source.params.walls.mu = 0.1: expected frames "
                "at most 0.12 of a cycle apart to read the compression phase, found 1.07 (lower "
                "source.params.save_every)\n")
    if r.returncode != 2 or r.stderr != expected:
        failures.append(f"frames a cycle apart: {r.returncode} {r.stderr!r}")
    whole = os.path.join(work, "whole")
    results(whole, np.arange(0.0, 3.05, 0.02))
    csv = os.path.join(work, "heights.csv")
    r = subprocess.run([sys.executable, script, whole, "--csv", csv], capture_output=True, text=True)
    rows = [line.split(",") for line in open(csv).read().splitlines()[2:]] if r.returncode == 0 else []
    heights = {(float(mu), int(c)): float(h) for mu, c, h in rows}
    want = {(mu, c): 10.0 * (c + 0.28) for mu in (0.1, 0.5) for c in range(3)}
    if r.returncode != 0 or set(heights) != set(want) or any(
            abs(heights[k] - want[k]) > 1e-9 for k in want):
        failures.append(f"three cycles: {r.returncode} {r.stderr!r} {heights}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("bnp_wall_friction.py: heights at the compression phase of the cycles reached")
