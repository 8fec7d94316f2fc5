#!/usr/bin/env python3
"""Speed against error of the `dem` source (issue 12): each point a separate granpipe run
(--threads 1), its cost the CPU seconds of that process (user + system, from
getrusage(RUSAGE_CHILDREN)): the machine is shared, so wall seconds would measure the
neighbours' load.

  collision  pipelines/dem_speed_vs_error.json: the head-on collision of two spheres at
             dt/t_c = 0.01 ... 0.08, each at 4 starts of the contact within a step;
             errors of the measured contact time and restitution coefficient against the
             linear law's analytic values (the `collision` analyzer). Its CPU time is mostly
             start-up; the steps per contact (t_c/dt) are the cost.
  bnp        pipelines/dem_speed_vs_error_bnp.json: the Brazil-nut bed shaken for 10 cycles at
             dt = 1e-4 ... 4e-4 (skin 0.2) and skin 0.1, 0.4 (dt 2e-4); the intruder's height
             after 10 cycles against the run at dt = 1e-4.

Each point's output goes to OUT/<point>/ and its CPU time to OUT/cpu_seconds.csv, so an
interrupted sweep resumes where it stopped (a point cut off mid-run leaves its directory:
remove it to run that point again). Writes the table to --csv, the plot to --plot, and a
markdown table to stdout.

    scripts/dem_speed_vs_error.py collision
    nice -n 19 scripts/dem_speed_vs_error.py bnp --out out/dem_speed_vs_error_bnp
"""
import argparse
import csv
import json
import math
import os
import resource
import subprocess
import sys

from charts import loglog_chart
from input_error import refuse, require_outputs
from result_csv import read_scalars, read_table

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COLLISION_FRACTIONS = [0.01, 0.02, 0.04, 0.06, 0.08]
PHASES = 4  # starts of the contact within a time step, per dt/t_c
BNP_POINTS = [(1e-4, 0.2), (2e-4, 0.2), (3e-4, 0.2), (4e-4, 0.2), (2e-4, 0.1), (2e-4, 0.4)]
BNP_REFERENCE = (1e-4, 0.2)


def cpu_seconds_of_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_point(args, pipeline, name, settings, cpu_log):
    """Runs one point unless cpu_log already has it; returns its CPU seconds."""
    if name in cpu_log:
        return cpu_log[name]
    out = os.path.join(args.out, name)
    if os.path.exists(out):
        refuse(f"{out}: expected no directory for a point not in cpu_seconds.csv, found one "
               "(an interrupted run?): remove it to run the point again")
    command = [args.granpipe, pipeline, "--out", out, "--threads", "1", "--quiet", "--no-report"]
    for key, value in settings.items():
        command += ["--set", f"{key}={json.dumps(value)}"]
    before = cpu_seconds_of_children()
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = cpu_seconds_of_children() - before
    if result.returncode != 0:
        message = f"{' '.join(command)}: exit {result.returncode}: {result.stderr.strip()}"
        if result.returncode == 2:  # granpipe refused the input: so does this script
            refuse(message)
        raise SystemExit(message)
    with open(os.path.join(args.out, "cpu_seconds.csv"), "a") as f:
        f.write(f"{name},{seconds!r}\n")
    cpu_log[name] = seconds
    print(f"{name}: {seconds:.3g} CPU s", file=sys.stderr)
    return seconds


def read_cpu_log(out):
    path = os.path.join(out, "cpu_seconds.csv")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return {name: float(seconds) for name, seconds in csv.reader(f)}


def collision_geometry(pipeline):
    """t_c of Eq. (10) for the collision pipeline's pair (the analyzer's k_n, gamma_n and
    densities, the radii and species of the start frame) and the time until the spheres touch."""
    import h5py  # only this scene reads a frames file

    with open(pipeline) as f:
        spec = json.load(f)
    params = spec["analyzers"][0]["params"]
    start = os.path.join(os.path.dirname(pipeline), spec["source"]["params"]["initial_file"])
    with h5py.File(start, "r") as f:
        x, v = f["particles/all/position/value"][0], f["particles/all/velocity/value"][0]
        radius = f["particles/all/radius/value"][0]
        species = f["particles/all/species/value"][0] if "particles/all/species" in f else [0, 0]
    mass = [params["density"][s] * 4.0 / 3.0 * math.pi * r**3 for r, s in zip(radius, species)]
    m_eff = mass[0] * mass[1] / (mass[0] + mass[1])
    t_c = math.pi / math.sqrt(params["k_n"] / m_eff - params["gamma_n"] ** 2 / 4.0)
    d = [a - b for a, b in zip(x[0], x[1])]
    distance = math.sqrt(sum(c * c for c in d))
    closing = -sum((a - b) * c for a, b, c in zip(v[0], v[1], d)) / distance
    return t_c, (distance - radius[0] - radius[1]) / closing


def collision(args, cpu_log):
    pipeline = os.path.join(ROOT, "pipelines", "dem_speed_vs_error.json")
    t_c, approach = collision_geometry(pipeline)
    rows = []
    for fraction in COLLISION_FRACTIONS:
        # Where the contact starts within a step moves the measured restitution by up to
        # about dt/t_c: each dt is run at PHASES starts, dt stretched by < 0.5 %.
        for phase in range(PHASES):
            dt = fraction * t_c
            dt *= 1.0 + phase / PHASES / (approach / dt)
            name = f"dt_tc_{fraction:g}_phase{phase}"
            seconds = run_point(args, pipeline, name, {"source.params.dt": dt}, cpu_log)
            s = read_scalars(os.path.join(args.out, name, "collision.scalars.csv"))
            rows.append({"dt_over_tc": dt / t_c, "phase": phase, "dt": dt, "cpu_seconds": seconds,
                         "steps_per_contact": t_c / dt, "contact_time": s["contact_time"][0],
                         "contact_time_rel_error": s["contact_time_rel_error"][0],
                         "restitution": s["restitution"][0],
                         "restitution_rel_error": s["restitution_rel_error"][0]})
    series = {}
    for q, label in (("contact_time_rel_error", "contact time"), ("restitution_rel_error", "restitution")):
        for fraction in COLLISION_FRACTIONS:
            worst = max(abs(r[q]) for r in rows if abs(r["dt_over_tc"] / fraction - 1.0) < 0.01)
            series.setdefault(f"{label} (largest of {PHASES} phases)", []).append((1.0 / fraction, worst, ""))
    summary = []
    for fraction in COLLISION_FRACTIONS:
        group = [r for r in rows if abs(r["dt_over_tc"] / fraction - 1.0) < 0.01]
        t_err = [r["contact_time_rel_error"] for r in group]
        e_err = [r["restitution_rel_error"] for r in group]
        summary.append({"dt/t_c": f"{fraction:g}", "CPU s (mean)": f"{sum(r['cpu_seconds'] for r in group) / len(group):.3f}",
                        "t_c error (mean)": f"{sum(t_err) / len(t_err):+.2%}",
                        "e error (range over phases)": f"{min(e_err):+.2%} to {max(e_err):+.2%}"})
    return rows, summary, series, "steps per contact time (t_c / dt)", "|relative error|"


def final_height(path):
    """Time and intruder height of the last row of an intruder.per_frame.csv."""
    _, header, rows = read_table(path)
    if not rows:
        refuse(f"{path}: expected rows, found none")
    return rows[-1][header.index("time")], rows[-1][header.index("intruder_height")]


def bnp(args, cpu_log):
    pipeline = os.path.join(ROOT, "pipelines", "dem_speed_vs_error_bnp.json")
    runs = {}
    for dt, skin in BNP_POINTS:
        name = f"dt{dt:g}_skin{skin:g}"
        # One frame per time unit at every dt, so that the per-frame tables share their times.
        settings = {"source.params.dt": dt, "source.params.skin": skin, "source.params.save_every": round(1.0 / dt)}
        seconds = run_point(args, pipeline, name, settings, cpu_log)
        runs[(dt, skin)] = (seconds, *final_height(os.path.join(args.out, name, "intruder.per_frame.csv")))
    _, _, reference = runs[BNP_REFERENCE]
    rows, series = [], {}
    for (dt, skin), (seconds, time, height) in runs.items():
        rows.append({"dt": dt, "skin": skin, "cpu_seconds": seconds, "time": time, "intruder_height": height,
                     "height_deviation": abs(height - reference)})
        if (dt, skin) != BNP_REFERENCE:
            series.setdefault(f"skin {skin:g}" if skin != BNP_REFERENCE[1] else "dt (skin 0.2)", []).append(
                (seconds, abs(height - reference), ""))
    summary = [{"dt": f"{r['dt']:g}", "skin": f"{r['skin']:g}", "CPU s": f"{r['cpu_seconds']:.0f}",
                "intruder height at t = 93.46": f"{r['intruder_height']:.2f}",
                "deviation from dt = 1e-4": f"{r['height_deviation']:.2f}"} for r in rows]
    return rows, summary, series, "CPU seconds (1 thread)", "|intruder height - height at dt = 1e-4|"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene", choices=["collision", "bnp"])
    ap.add_argument("--granpipe", default=os.path.join(ROOT, "build", "bin", "granpipe"))
    ap.add_argument("--out", help="directory of the runs (default out/dem_speed_vs_error[_bnp])")
    ap.add_argument("--csv", help="table to write (default docs/data/dem_speed_vs_error_<scene>.csv)")
    ap.add_argument("--plot", help="figure to write (default docs/img/dem_speed_vs_error_<scene>.svg)")
    args = ap.parse_args()
    args.out = args.out or os.path.join("out", "dem_speed_vs_error" + ("_bnp" if args.scene == "bnp" else ""))
    args.csv = args.csv or os.path.join(ROOT, "docs", "data", f"dem_speed_vs_error_{args.scene}.csv")
    args.plot = args.plot or os.path.join(ROOT, "docs", "img", f"dem_speed_vs_error_{args.scene}.svg")
    # The runs' folder holds the CPU log read back: the table and figure never replace it.
    require_outputs([args.csv, args.plot], runs=[args.out])
    os.makedirs(args.out, exist_ok=True)
    cpu_log = read_cpu_log(args.out)
    rows, summary, series, xlabel, ylabel = (collision if args.scene == "collision" else bnp)(args, cpu_log)
    with open(args.csv, "w", newline="") as f:
        f.write(f"# scripts/dem_speed_vs_error.py {args.scene}: one granpipe process per point, --threads 1\n")
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    loglog_chart(series, xlabel, ylabel, args.plot)
    print("| " + " | ".join(summary[0]) + " |")
    print("|" + "---|" * len(summary[0]))
    for r in summary:
        print("| " + " | ".join(r.values()) + " |")


if __name__ == "__main__":
    main()
