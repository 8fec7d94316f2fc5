#!/usr/bin/python3
"""The Brazil-nut scene at 7.6*10^3, 7.6*10^4 and 7.6*10^5 spheres, granpipe beside LAMMPS (issue 22).

usage: dem_scaling.py [--build DIR] [--copies 1 10 100] [--warmup STEPS] [--timed STEPS]
                      [--cores 1 2] [--without-lammps] [--keep DIR]

The settled bed of the reference runs (../shared/bench/bnp/settled.data.gz: 7600 small
spheres and the intruder in the cylinder of diameter 12.25) is stacked `copies` times in
a taller cylinder, each copy 57 above the one below (its highest centre is at 56.0, so each
falls by about half a diameter onto the one below). Both engines start from that one data
file: LAMMPS reads it, granpipe imports it with its lammps_data source. Then the scene of
bnp_side_by_side.py (same contact law, parameters, time step, skin, walls and drive) runs
`warmup` steps and `timed` ones, on 1 and 2 threads or ranks, the engines interleaved.

Prints a Markdown table: particle-steps per second of the timed steps (granpipe: its
source/timing rows after the first; LAMMPS: the second run's loop time), their ratio, and
memory: the peak resident size of the 1-thread / 1-rank process (wait4's ru_maxrss), per
sphere, and per sphere added from one size to the next (which leaves out what the process
holds whatever the size: libraries, plugins, MPI).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bnp_side_by_side as bnp  # noqa: E402  (the scene and its runs)

LAYER = 57.0  # height between two stacked copies of the settled bed


def atoms_of(settled):
    """The Atoms rows of the settled packing's data file, as word lists."""
    rows, current = [], None
    for line in settled.splitlines():
        text = line.split("#")[0].strip()
        if not text:
            continue
        if text[0].isalpha():
            current = text
        elif current == "Atoms":
            rows.append(text.split())
    return rows


def stacked_data(settled, copies):
    """A LAMMPS data file (atom_style sphere) of `copies` copies of the bed, stacked in z."""
    rows = atoms_of(settled)
    top = copies * LAYER + 30.0
    lines = []
    for c in range(copies):
        for w in rows:
            atom = c * len(rows) + int(w[0])
            z = float(w[6]) + c * LAYER
            lines.append(f"{atom} {w[1]} {w[2]} {w[3]} {w[4]} {w[5]} {z!r} 0 0 0")
    return (f"BNP settled packing stacked {copies} times\n\n{len(lines)} atoms\n2 atom types\n\n"
            f"-6.3 6.3 xlo xhi\n-6.3 6.3 ylo yhi\n-1 {top} zlo zhi\n\nAtoms # sphere\n\n"
            + "\n".join(lines) + "\n"), len(lines), top


def import_pipeline(top):
    return {"name": "dem_scaling_import",
            "description": "The stacked settled bed (tests/bench/dem_scaling.py) as one frame",
            "seed": 1,
            "source": {"plugin": "lammps_data",
                       "params": {"file": "settled.data", "base": 0.0, "cylinder_radius": bnp.CYLINDER_RADIUS,
                                  "top": top}},
            "analyzers": [], "output": {"dir": "imported"}}


def prepare(work, settled, copies, build, engines, args):
    """The run folder of one size: the data file, its import and both engines' inputs."""
    folder = os.path.join(work, f"copies_{copies}")
    os.makedirs(folder)
    data, n, top = stacked_data(settled, copies)
    with open(os.path.join(folder, "settled.data"), "w") as f:
        f.write(data)
    with open(os.path.join(folder, "import.json"), "w") as f:
        json.dump(import_pipeline(top), f)
    env = dict(os.environ, GRANPIPE_PLUGIN_PATH=os.path.join(build, "lib", "granpipe", "plugins"))
    subprocess.run([os.path.join(build, "bin", "granpipe"), "import.json", "--quiet", "--no-report", "--out",
                    "imported"], cwd=folder, env=env, check=True)
    pipeline = bnp.granpipe_pipeline(args.warmup + args.timed, args.warmup)
    pipeline["source"]["params"]["initial_file"] = os.path.join(folder, "imported", "frames.h5")
    files = {"granpipe.json": json.dumps(pipeline, indent=1)}
    if "LAMMPS" in engines:
        files["in.lammps"] = bnp.LAMMPS_INPUT
    for name, text in files.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    return folder, n


def run_once(folder, engine, cores, build, args):
    label = f"{engine}_{cores}"
    print(f"running {os.path.basename(folder)} {label} ...", file=sys.stderr, flush=True)
    if engine == "granpipe":
        r = bnp.run_granpipe(folder, build, cores, label, args.warmup + args.timed)
        r["timed"] = r["profile"]["seconds"]
    else:
        r = bnp.run_engine(folder, "LAMMPS", cores, label, args)
    r["peak_bytes"] = r["maxrss_kb"] * 1024
    return r


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(bnp.REPO, "build"), help="granpipe build or install folder")
    parser.add_argument("--ref-dir", default=os.path.join(bnp.REPO, "..", "shared", "bench", "bnp"),
                        help="folder with settled.data(.gz) (default: ../shared/bench/bnp)")
    parser.add_argument("--copies", type=int, nargs="+", default=[1, 10, 100])
    parser.add_argument("--warmup", type=int, default=500, help="warm-up steps, also the frame interval")
    parser.add_argument("--timed", type=int, default=1000, help="timed steps, a multiple of --warmup")
    parser.add_argument("--cores", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--without-lammps", action="store_true")
    parser.add_argument("--keep", help="run in this new folder and keep it instead of a temporary one")
    args = parser.parse_args()
    if args.timed % args.warmup:
        raise SystemExit(f"--timed: expected a multiple of --warmup, got {args.timed}")
    build = os.path.abspath(args.build)
    engines = ["granpipe"] + ([] if args.without_lammps or shutil.which("lmp") is None else ["LAMMPS"])
    settled = bnp.read_settled(args.ref_dir)
    start, load = time.strftime("%Y-%m-%d %H:%M"), os.getloadavg()[0]
    records = []
    with tempfile.TemporaryDirectory() as tmp:
        work = args.keep or tmp
        os.makedirs(work, exist_ok=True)
        for copies in args.copies:
            folder, n = prepare(work, settled, copies, build, engines, args)
            for cores in args.cores:
                for engine in engines:
                    r = run_once(folder, engine, cores, build, args)
                    records.append(dict(r, copies=copies, n=n, engine=engine, cores=cores))
        kernels = sorted({r["kernels"] for r in records if r["engine"] == "granpipe"})
    print(f"\n{start}, {bnp.machine()}, load average {load:.2f} at the start, {os.getloadavg()[0]:.2f} at the end; "
          f"{args.warmup} warm-up + {args.timed} timed steps; granpipe's force loops: {', '.join(kernels)}\n")
    report(records, engines, args)


def record_of(records, engine, copies, cores):
    return next((r for r in records if (r["engine"], r["copies"], r["cores"]) == (engine, copies, cores)), None)


def report(records, engines, args):
    print("| spheres | threads / ranks | granpipe particle-steps/s | LAMMPS particle-steps/s | granpipe / LAMMPS |")
    print("|---|---|---|---|---|")
    for copies in args.copies:
        for cores in args.cores:
            rates = {}
            for engine in engines:
                r = record_of(records, engine, copies, cores)
                rates[engine] = r["n"] * args.timed / r["timed"]
            n = record_of(records, "granpipe", copies, cores)["n"]
            lammps = rates.get("LAMMPS")
            ratio = f"**{rates['granpipe'] / lammps:.2f}**" if lammps else ""
            lammps_text = f"{lammps:.3g}" if lammps else ""
            print(f"| {n} | {cores} | {rates['granpipe']:.3g} | {lammps_text} | {ratio} |")
    if 1 not in args.cores:
        return
    print("\n| spheres | engine | peak resident MB (1 thread / rank) | bytes per sphere | added per sphere |")
    print("|---|---|---|---|---|")
    for engine in engines:
        before = None
        for copies in args.copies:
            r = record_of(records, engine, copies, 1)
            added = "" if before is None else f"{(r['peak_bytes'] - before['peak_bytes']) / (r['n'] - before['n']):.0f}"
            print(f"| {r['n']} | {engine} | {r['peak_bytes'] / 2**20:.0f} | {r['peak_bytes'] / r['n']:.0f} | {added} |")
            before = r


if __name__ == "__main__":
    main()
