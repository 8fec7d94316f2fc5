"""granpipe's whole pores analysis against CGAL's bare Delaunay triangulation of the same
centres and against scipy's Delaunay (Qhull), side by side in one run (issue 20).

    /usr/bin/python3 tests/bench/pores_vs_qhull.py BUILD [--sizes 1e5 1e6] [--work DIR]
                                                   [--repeats 2] [--seed 21] [--without-qhull]

The packings are granpipe's own random packings: sequential gravitational depositions
(the spheres3d_tap source, Jullien-Meakin steepest descent, taps 0) of N spheres of
radius 1 in a square box of side (N (4 pi / 3) / 0.58)^(1/3), so that the packing is about
a cube (packing fraction about 0.58 below its surface), with side walls (F.B.C.) or
periodic sides (P.B.C.), a bottom wall and an open top. They are made once and kept in
the work folder (default BUILD/pores_vs_qhull); every program then reads the same centres.
A deposition can stall (the source gives up on a sphere that does not come to rest within
100000 stages, e.g. 2*10^4 spheres with walls and seed 21); the next seed is then tried,
and the table names the seed of each packing.

Each measurement is a process of its own, run in turn (bare, bare on huge pages, analysis
on one thread, on two, Qhull) and repeated; the table holds the medians of the timed part alone (reading
the frame excluded): wall-clock seconds, processor seconds of all threads, and the memory
it added to the process's peak resident size, per sphere (wait4's ru_maxrss less the peak
before the timed part). The analysis is bench_pores' (measure_pores with region
inner, margin 2 R, and the histograms): triangulation of the centres and of the periodic
images, circumspheres, degenerate merge, histograms and Voronoi volumes (cells at the
walls cut there). --without-qhull leaves Qhull out (minutes a run at 10^6 spheres).
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys

PACKING_FRACTION = 0.58
# granpipe (and bench_pores analysis) run themselves again with glibc's malloc on
# transparent huge pages; "CGAL bare, THP" is the bare triangulation given the same heap.
HUGE_PAGES = dict(os.environ, GLIBC_TUNABLES="glibc.malloc.hugetlb=1")

QHULL = """
import resource, sys, time
import numpy as np
from scipy.spatial import Delaunay
points = np.fromfile(sys.argv[1], dtype="<f8").reshape(-1, 3)
print("memory_before_kb", resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
start, cpu_start = time.perf_counter(), time.process_time()
cells = len(Delaunay(points).simplices)
print("seconds", time.perf_counter() - start)
print("cpu_seconds", time.process_time() - cpu_start)
print("cells", cells)
"""


def run(command, env=None):
    """The child's printed "key value" lines, and its peak resident size in kB."""
    child = subprocess.Popen(command, stdout=subprocess.PIPE, text=True, env=env)
    out = child.stdout.read()
    _, status, usage = os.wait4(child.pid, 0)
    if status != 0:
        sys.exit(f"{' '.join(command[:2])}: exit status {status}")
    values = dict(line.split(maxsplit=1) for line in out.splitlines() if line.strip())
    values["peak_kb"] = usage.ru_maxrss
    return values


def deposit_once(build, work, n, sides, seed):
    """The deposition's frames.h5, made unless kept from an earlier run; None if it
    stalled (then or in an earlier run: the source's message is kept beside it)."""
    name = f"deposit_{n}_{sides}_seed{seed}"
    frames = os.path.join(work, name, "frames.h5")
    stalled = os.path.join(work, name + ".stalled")
    if os.path.exists(frames) or os.path.exists(stalled):
        return frames if os.path.exists(frames) else None
    side = round((n * 4.0 * math.pi / 3.0 / PACKING_FRACTION) ** (1.0 / 3.0))
    pipeline = {
        "name": name, "seed": seed,
        "source": {"plugin": "spheres3d_tap",
                   "params": {"N": n, "side": side, "sides": sides, "taps": 0,
                              "log_frames": False}},
        "analyzers": [],
        "output": {"dir": os.path.join(work, name), "save_frames": True}}
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(pipeline, f)
    print(f"depositing {n} spheres, {sides} sides (box side {side}), seed {seed}", flush=True)
    made = subprocess.run([f"{build}/bin/granpipe", path, "--quiet", "--no-report", "--overwrite"],
                          stderr=subprocess.PIPE, text=True)
    if made.returncode == 0:
        return frames
    if "did not come to rest" not in made.stderr:
        sys.exit(made.stderr.strip() or f"{path}: exit status {made.returncode}")
    print(made.stderr.strip(), flush=True)
    with open(stalled, "w") as f:
        f.write(made.stderr)
    return None


def deposit(build, work, n, sides, first_seed, attempts=5):
    """The frames.h5 and seed of the first of `attempts` seeds whose deposition ends."""
    for seed in range(first_seed, first_seed + attempts):
        frames = deposit_once(build, work, n, sides, seed)
        if frames:
            return frames, seed
    sys.exit(f"{n} spheres, {sides} sides: the deposition stalled with seeds {first_seed} "
             f"to {first_seed + attempts - 1}")


def measurements(build, frames, points, repeats, with_qhull):
    """Per program, the runs' values; the programs take turns, so that a change of the
    machine's load falls on all of them."""
    bench = f"{build}/bin/bench_pores"
    programs = {"CGAL bare": ([bench, "bare", frames], None),
                "CGAL bare, THP": ([bench, "bare", frames], HUGE_PAGES),
                "granpipe 1 thread": ([bench, "analysis", frames, "1"], None),
                "granpipe 2 threads": ([bench, "analysis", frames, "2"], None)}
    if with_qhull:
        programs["Qhull"] = (["/usr/bin/python3", "-c", QHULL, points], None)
    runs = {name: [] for name in programs}
    for _ in range(repeats):
        for name, (command, env) in programs.items():
            runs[name].append(run(command, env))
            print(f"  {name}: {float(runs[name][-1]['seconds']):.3f} s", flush=True)
    return runs


def summary(values):
    """Median seconds, processor seconds and memory added (kB), over the runs."""
    seconds = statistics.median(float(v["seconds"]) for v in values)
    cpu = statistics.median(float(v["cpu_seconds"]) for v in values)
    added = statistics.median(v["peak_kb"] - int(v["memory_before_kb"]) for v in values)
    return seconds, cpu, added


def machine():
    out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    fields = dict(line.split(":", 1) for line in out.splitlines() if ":" in line)
    flags = fields.get("Flags", "").split()
    simd = [f for f in flags if f.startswith(("sse", "ssse", "avx", "fma"))]
    return (f"{fields.get('Model name', '?').strip()}, {fields.get('CPU(s)', '?').strip()} CPUs, "
            f"load average {os.getloadavg()[0]:.1f}\nSIMD flags: {' '.join(simd)}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build")
    parser.add_argument("--sizes", nargs="+", type=float, default=[1e5, 1e6])
    parser.add_argument("--work")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--seed", type=int, default=21)
    parser.add_argument("--without-qhull", action="store_true")
    args = parser.parse_args()
    work = args.work or os.path.join(args.build, "pores_vs_qhull")
    print(machine())
    rows = []
    for n in (int(s) for s in args.sizes):
        for sides in ("walls", "periodic"):
            frames, seed = deposit(args.build, work, n, sides, args.seed)
            points = os.path.join(work, f"points_{n}_{sides}_seed{seed}.bin")
            run([f"{args.build}/bin/bench_pores", "points", frames, points])
            runs = measurements(args.build, frames, points, args.repeats, not args.without_qhull)
            bare = summary(runs["CGAL bare"])[0]
            bare_thp = summary(runs["CGAL bare, THP"])[0]
            qhull = summary(runs["Qhull"])[0] if "Qhull" in runs else math.nan
            for name, values in runs.items():
                seconds, cpu, added = summary(values)
                rows.append((n, sides, seed, name, seconds, cpu, seconds / bare,
                             seconds / bare_thp, qhull / seconds, added * 1024.0 / n))
    print(f"\n{'N':>8} {'sides':>8} {'seed':>4} {'program':>18} {'s':>8} {'CPU s':>8} "
          f"{'/ bare':>7} {'/ THP':>7} {'Qhull /':>8} {'bytes/sphere':>12}")
    for n, sides, seed, name, seconds, cpu, to_bare, to_thp, qhull_ratio, per_sphere in rows:
        print(f"{n:>8} {sides:>8} {seed:>4} {name:>18} {seconds:>8.3f} {cpu:>8.2f} "
              f"{to_bare:>7.2f} {to_thp:>7.2f} {qhull_ratio:>8.2f} {per_sphere:>12.0f}")
    print("\ntargets (issue 20): analysis / bare <= 1.5; Qhull / analysis >= 5")


if __name__ == "__main__":
    main()
