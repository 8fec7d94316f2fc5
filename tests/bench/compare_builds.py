#!/usr/bin/python3
"""Two builds (two commits) side by side: the 2D benchmarks and a small tap2d pipeline.

usage: compare_builds.py OLD_BUILD NEW_BUILD [--rounds N]

The builds run alternately, round after round, so that the noise of a shared machine hits
both alike; each figure is the median over rounds, and the ratio new/old is the figure to
quote (below 1: the new build is faster).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

BENCHMARKS = [("bench_disks2d_tap", "BM_Tap/500|BM_Tap/2000"),
              ("bench_packing", "BM_MeasurePacking/16|BM_MeasurePacking/32")]
PIPELINE = ["pipelines/tap2d_arches.json", "--set", "source.params.N=500",
            "--set", "source.params.equilibration_taps=20", "--set", "source.params.production_taps=20",
            "--threads", "1", "--quiet", "--no-report"]


def run_benchmark(build, exe, pattern):
    out = subprocess.run([os.path.join(build, "bin", exe), f"--benchmark_filter={pattern}",
                          "--benchmark_format=json", "--benchmark_min_time=0.5"],
                         check=True, capture_output=True, text=True).stdout
    runs = [b for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
    failed = [b["name"] + ": " + b.get("error_message", "") for b in runs if "real_time" not in b]
    if failed:
        raise SystemExit(f"{build}/bin/{exe}: " + "; ".join(failed))
    return {b["name"]: b["real_time"] * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
            for b in runs}


def run_pipeline(build, source_dir):
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, GRANPIPE_PLUGIN_PATH=os.path.join(build, "lib", "granpipe", "plugins"))
        start = time.perf_counter()
        subprocess.run([os.path.join(build, "bin", "granpipe")] + PIPELINE + ["--out", os.path.join(tmp, "run")],
                       check=True, cwd=source_dir, env=env, capture_output=True)
        return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    source_dir = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    times = {"old": {}, "new": {}}
    for _ in range(args.rounds):
        for label, build in (("old", args.old), ("new", args.new)):
            for exe, pattern in BENCHMARKS:
                for name, t in run_benchmark(build, exe, pattern).items():
                    times[label].setdefault(name, []).append(t)
            times[label].setdefault("tap2d_arches pipeline (18 amplitudes x 40 taps, N = 500)", []).append(
                run_pipeline(build, source_dir))
    print("| case | old | new | new / old |")
    print("|---|---|---|---|")
    for name in times["old"]:
        old, new = statistics.median(times["old"][name]), statistics.median(times["new"][name])
        print(f"| {name} | {old * 1e3:.1f} ms | {new * 1e3:.1f} ms | {new / old:.3f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
