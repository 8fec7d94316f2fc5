#!/usr/bin/env python3
"""The paper's Fig. 7 from a run of pipelines/bnp_wall_friction.json: the intruder's height
above the base against the shaking cycles, one curve per wall friction coefficient.

    scripts/bnp_wall_friction.py OUT_DIR [--csv docs/data/bnp_wall_friction.csv]
                                 [--figure docs/img/bnp_wall_friction.svg]

Reads OUT_DIR/results.h5 (or results.partial.h5 of a run still going). Within a cycle the
whole bed flies and lands, so the intruder's height is read once per cycle, at the phase of
the compression stage (0.28 of a period after the container's lowest point, where the bed
sits on the base: docs/bnp_mst.md); prints a markdown table of it every 5 cycles and writes
the once-per-cycle curves as CSV and as a figure."""
import argparse
import json
import math
import os
import statistics

import h5py

from charts import line_chart
from input_error import read_pipeline, refuse, require_outputs

SWEPT = "source.params.walls.mu"
COMPRESSION_PHASE = 0.28
# How far from the compression phase a frame may lie and still give its height (the kept
# runs' frames lie 0.107 of a cycle apart, none farther than 0.0535 from the phase; a bed in
# flight half a cycle off read as one at rest).
PHASE_TOLERANCE = 0.06


def read_curves(path):
    """{mu: [(cycles, intruder height)]} of every point of the sweep in `path`."""
    with h5py.File(path, "r", swmr=True) as f:
        if "pipeline" in f.attrs:
            pipeline = json.loads(f.attrs["pipeline"])
        else:
            pipeline = read_pipeline(os.path.dirname(path))
        values = pipeline["sweep"]["parameters"][SWEPT]
        curves = {}
        for k, mu in enumerate(values):
            table = f[f"point_{k:03d}/intruder/per_frame"]
            # The source's own count of drive periods (time x frequency ignored a drive's start).
            curves[mu] = list(zip(table["cycles"][()], table["intruder_height"][()]))
    return curves


def height_at(points, cycle, reach):
    """The height in the frame nearest to `cycle` + the compression phase, or None where no
    frame lies within `reach` of it (a run short of its first: the last frame's height was
    given as cycle 0's)."""
    nearest = min(points, key=lambda p: abs(p[0] - cycle - COMPRESSION_PHASE))
    return nearest[1] if abs(nearest[0] - cycle - COMPRESSION_PHASE) <= reach else None


def frame_spacing(points):
    """The frames' usual distance in cycles (frames before a drive's start, all at cycle 0,
    left out: their spacing of 0 made every reach 0)."""
    steps = [b[0] - a[0] for a, b in zip(points, points[1:]) if b[0] > a[0]]
    return statistics.median(steps) if steps else float("inf")


def per_cycle(points):
    """[(cycle, height at its compression phase)] of the cycles a frame reaches within
    PHASE_TOLERANCE."""
    last = math.floor(points[-1][0] - COMPRESSION_PHASE)
    heights = [(c, height_at(points, c, PHASE_TOLERANCE)) for c in range(0, last + 1)]
    return [(c, h) for c, h in heights if h is not None]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out_dir")
    parser.add_argument("--csv")
    parser.add_argument("--figure")
    args = parser.parse_args()
    require_outputs([o for o in (args.csv, args.figure) if o], runs=[args.out_dir])
    final = os.path.join(args.out_dir, "results.h5")
    path = final if os.path.exists(final) else os.path.join(args.out_dir, "results.partial.h5")
    if not os.path.exists(path):
        refuse(f"{args.out_dir}: expected results.h5 or results.partial.h5 of a run, found neither")
    try:
        curves = read_curves(path)
    except (OSError, KeyError, TypeError) as e:
        refuse(f"{path}: expected the results of a run of pipelines/bnp_wall_friction.json, "
               f"could not read them ({type(e).__name__}: {e})")
    for mu, points in curves.items():
        if not points or not all(math.isfinite(c) for c, _ in points):
            refuse(f"{path}: the point of {SWEPT} = {mu}: expected frames counting the drive's "
                   "cycles (the intruder's cycles column), found frames without")
        spacing = frame_spacing(points)
        # (No step at all, every frame before the drive's start: refused below, as reaching
        # no compression.)
        if 2.0 * PHASE_TOLERANCE < spacing < float("inf"):
            refuse(f"{path}: the point of {SWEPT} = {mu}: expected frames at most "
                   f"{2.0 * PHASE_TOLERANCE:g} of a cycle apart to read the compression phase, "
                   f"found {spacing:.3g} (lower source.params.save_every)")
    cycles = {mu: per_cycle(points) for mu, points in curves.items()}
    if any(not c for c in cycles.values()):
        reached = min(points[-1][0] for points in curves.values())
        refuse(f"{path}: expected a run reaching the compression phase ({COMPRESSION_PHASE}) of a "
               f"cycle, found frames up to cycle {reached:.3g}")
    print("| cycle | " + " | ".join(f"μ_wall = {mu}" for mu in cycles) + " |")
    print("|---|" + "---|" * len(cycles))
    # Rows by cycle: each curve's height at that cycle (undefined where it has none).
    heights = {mu: dict(points) for mu, points in cycles.items()}
    for c in sorted(set.intersection(*(set(h) for h in heights.values())))[::5]:
        print(f"| {c} | " + " | ".join(f"{h[c]:.1f}" for h in heights.values()) + " |")
    if args.csv:
        with open(args.csv, "w") as out:
            # Relative to where the script runs, so no machine's absolute path lands in a kept table.
            out.write(f"# {os.path.relpath(path)}: intruder height above the base at phase {COMPRESSION_PHASE} of each cycle\n")
            out.write("mu_wall,cycle,intruder_height\n")
            for mu, points in cycles.items():
                for c, h in points:
                    out.write(f"{mu},{c},{h:.4f}\n")
    if args.figure:
        series = {f"μ_wall = {mu}": [(c, h, float("nan")) for c, h in p] for mu, p in cycles.items()}
        line_chart(series, [], "cycles", "intruder height above the base at compression (d₀)", args.figure)


if __name__ == "__main__":
    main()
