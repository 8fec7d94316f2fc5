#!/usr/bin/python3
"""The Brazil-nut scene on a machine shared with one other CPU-bound process (issue 22).

usage: dem_shared_machine.py --builds DIR[=LABEL] [DIR[=LABEL] ...] [--rounds N]
                             [--warmup STEPS] [--timed STEPS] [--without-lammps] [--whole-runs]

The scene, inputs and timing are bnp_side_by_side.py's (the settled bed shaken from rest,
the timed seconds those of the dem source's timing table after the warm-up interval). Each
round runs every build (an install or build folder) on 1 and on 2 threads, and LAMMPS on
1 and 2 ranks, first on the quiet machine and then beside a competing process (a Python
busy loop this script starts and stops), all interleaved so that other load hits all alike.
Prints a Markdown table: seconds per run (medians over the rounds) and the ratio of the
2-thread run to the 1-thread run, quiet and busy, with the steps granpipe's thread governor
ran on one thread (from run.log). The target: busy, 2 threads no slower than 1.
--whole-runs times whole runs (the process's wall time, start and warm-up included) instead:
for short runs, whose first second decides.
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bnp_side_by_side as bnp  # noqa: E402  (the scene, its inputs and the timed runs)


def fewer_thread_steps(run_log):
    """Steps the dem source ran on one thread instead of all (its run.log line), or 0."""
    with open(run_log) as f:
        for line in f:
            found = re.match(r"dem: (\d+) of (\d+) steps ran on 1 thread", line)
            if found:
                return int(found.group(1)) / int(found.group(2))
    return 0.0


class Competitor:
    """One CPU-bound process for as long as the `with` block runs."""

    def __enter__(self):
        self.process = subprocess.Popen([sys.executable, "-c", "while True: pass"])
        time.sleep(0.5)
        return self

    def __exit__(self, *exc):
        self.process.kill()
        self.process.wait()


def one_round(work, args, rnd, records):
    for load in ("quiet", "busy"):
        with Competitor() if load == "busy" else open(os.devnull):
            for cores in (1, 2):
                # Alternate the builds' order from round to round: the second of two runs
                # back to back was measured up to 10 % slower whichever build it was.
                for build, label in args.builds[::1 if rnd % 2 else -1]:
                    name = f"{label}_{load}_{cores}_{rnd}"
                    print(f"running {name} ...", file=sys.stderr, flush=True)
                    r = bnp.run_granpipe(work, build, cores, name, args.warmup + args.timed)
                    r["timed"] = r["wall"] if args.whole_runs else r["profile"]["seconds"]
                    r["fewer"] = fewer_thread_steps(os.path.join(work, name, "out", "run.log"))
                    records.append(dict(r, program=label, load=load, cores=cores))
                if not args.without_lammps:
                    name = f"LAMMPS_{load}_{cores}_{rnd}"
                    print(f"running {name} ...", file=sys.stderr, flush=True)
                    r = bnp.run_engine(work, "LAMMPS", cores, name, args)
                    if args.whole_runs:
                        r["timed"] = r["wall"]
                    records.append(dict(r, program="LAMMPS", load=load, cores=cores, fewer=None))


def median_of(records, program, load, cores, key):
    values = [r[key] for r in records if (r["program"], r["load"], r["cores"]) == (program, load, cores)]
    return statistics.median(values) if values else float("nan")


def report(records, programs):
    print("| program | machine | 1 thread/rank s | 2 threads/ranks s | 2 / 1 | steps on 1 thread (2-thread run) |")
    print("|---|---|---|---|---|---|")
    for program in programs:
        for load in ("quiet", "busy"):
            one, two = (median_of(records, program, load, c, "timed") for c in (1, 2))
            fewer = median_of(records, program, load, 2, "fewer") if program != "LAMMPS" else None
            fewer_text = "" if fewer is None else f"{100 * fewer:.1f} %"
            print(f"| {program} | {load} | {one:.2f} | {two:.2f} | **{two / one:.2f}** | {fewer_text} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--builds", nargs="+", required=True, help="granpipe install or build folders, DIR[=LABEL]")
    parser.add_argument("--ref-dir", default=os.path.join(bnp.REPO, "..", "shared", "bench", "bnp"),
                        help="folder with settled.data(.gz), for LAMMPS (default: ../shared/bench/bnp)")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--warmup", type=int, default=2000, help="warm-up steps, also the frame interval")
    parser.add_argument("--timed", type=int, default=10000, help="timed steps, a multiple of --warmup")
    parser.add_argument("--without-lammps", action="store_true")
    parser.add_argument("--whole-runs", action="store_true", help="time whole runs, start included")
    args = parser.parse_args()
    if args.timed % args.warmup:
        raise SystemExit(f"--timed: expected a multiple of --warmup, got {args.timed}")
    args.without_lammps = args.without_lammps or shutil.which("lmp") is None
    args.builds = [(os.path.abspath(b.split("=", 1)[0]), b.split("=", 1)[1] if "=" in b else os.path.basename(b.rstrip("/")))
                   for b in args.builds]
    start, load = time.strftime("%Y-%m-%d %H:%M"), os.getloadavg()[0]
    records = []
    with tempfile.TemporaryDirectory() as work:
        engines = ["granpipe"] + ([] if args.without_lammps else ["LAMMPS"])
        bnp.write_inputs(work, args.ref_dir, engines, args.warmup + args.timed, args.warmup)
        for rnd in range(1, args.rounds + 1):
            one_round(work, args, rnd, records)
    kernels = sorted({r["kernels"] for r in records if r["program"] != "LAMMPS"})
    print(f"\n{start}, {bnp.machine()}, load average {load:.2f} at the start, {os.getloadavg()[0]:.2f} at the end; "
          f"N = {bnp.N_PARTICLES}, {args.warmup} warm-up + {args.timed} timed steps"
          f"{' (whole runs timed)' if args.whole_runs else ''}, medians of {args.rounds} "
          f"round(s); granpipe's force loops: {', '.join(kernels)}\n")
    report(records, [label for _, label in args.builds] + ([] if args.without_lammps else ["LAMMPS"]))


if __name__ == "__main__":
    main()
