#!/usr/bin/env python3
"""Run time against error for a resolution sweep (the design's "speed against error").

Reads a sweep's sweep.points.csv, takes the point with the finest resolution in each group
of the other swept parameters as the converged reference, and writes, beside the CSV,
speed_vs_error.csv (seconds and |deviation| of each quantity, with the reference's standard
error for scale) and speed_vs_error.svg (seconds against |deviation|, log-log).

    scripts/speed_vs_error.py out/tap2d_delta_study \
        --knob source.params.delta --time source.seconds \
        --quantity packing.phi --quantity arches.z_support_eq4

With --pool PARAMETER (e.g. source.params.replica), each value of that swept parameter is
its own group with its own reference, and the table has, per knob value, the mean over them
of the seconds and of each |deviation|, with the standard error of that mean (_err).
"""
import math
import statistics
import argparse
import csv
import os

from charts import loglog_chart
from input_error import read_pipeline, refuse
from result_csv import read_table


def read_points(path):
    _, header, rows = read_table(path)
    return [dict(zip(header, row)) for row in rows], header


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", help="output directory of a sweep run")
    ap.add_argument("--knob", required=True, help="swept resolution column; its smallest value is the reference")
    ap.add_argument("--time", required=True, help="column holding the run time of a point")
    ap.add_argument("--quantity", action="append", required=True, help="result column to compare (repeatable)")
    ap.add_argument("--pool", help="swept parameter (e.g. replicas) to average the deviations over")
    args = ap.parse_args()

    points, header = read_points(os.path.join(args.out, "sweep.points.csv"))
    for col in [args.knob, args.time] + args.quantity:
        if col not in header:
            refuse(f"{args.out}/sweep.points.csv: expected a column {col}, got none")
    swept = [h for h in header[1:header.index(args.knob)] + header[header.index(args.knob) + 1:]
             if h.startswith(("source.params.", "analyzers["))]
    # String-valued sweep parameters appear as their index in the sweep list.
    lists = read_pipeline(args.out).get("sweep", {}).get("parameters", {})
    name_of = lambda s, v: lists[s][int(v)] if s in lists and isinstance(lists[s][0], str) else f"{v:g}"
    groups = {}
    for p in points:
        groups.setdefault(tuple(p[s] for s in swept), []).append(p)

    rows, series = [], {}
    for key, members in sorted(groups.items()):
        ref = min(members, key=lambda p: p[args.knob])
        tag = ", ".join(f"{s.split('.')[-1]}={name_of(s, v)}" for s, v in zip(swept, key)) or "all"
        for p in sorted(members, key=lambda p: -p[args.knob]):
            row = {"group": tag, args.knob: p[args.knob], "seconds": p[args.time]}
            for q in args.quantity:
                row[q] = p[q]
                row[q + "_deviation"] = abs(p[q] - ref[q])
                row[q + "_reference_err"] = ref.get(q + "_err", float("nan"))
                if p is not ref:
                    series.setdefault(f"{q} ({tag})", []).append((p[args.time], abs(p[q] - ref[q]), f"{args.knob}={p[args.knob]:g}"))
            rows.append(row)
    if args.pool:
        if args.pool not in swept:
            refuse(f"{args.out}/sweep.points.csv: --pool {args.pool}: expected a swept parameter, got none")
        rows, series = pooled(rows, swept, args)
    with open(os.path.join(args.out, "speed_vs_error.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    loglog_chart(series, "run time of the point (s)", "|deviation from the finest point|",
             os.path.join(args.out, "speed_vs_error.svg"))
    cols = ["group", args.knob, "seconds"] + [q + "_deviation" for q in args.quantity]
    if args.pool:
        cols += [q + "_deviation_err" for q in args.quantity]
    print("  ".join(f"{c:>24}" for c in cols))
    for r in rows:
        print("  ".join(f"{r[c]:>24}" if isinstance(r[c], str) else f"{r[c]:>24.4g}" for c in cols))


def pooled(rows, swept, args):
    """The rows averaged over the values of args.pool: one row per (other groups, knob)."""
    pool_name = args.pool.split(".")[-1]
    keep = lambda tag: ", ".join(t for t in tag.split(", ") if not t.startswith(pool_name + "=")) or "all"
    groups = {}
    for r in rows:
        groups.setdefault((keep(r["group"]), r[args.knob]), []).append(r)
    out, series = [], {}
    for (tag, knob), members in sorted(groups.items(), key=lambda kv: (kv[0][0], -kv[0][1])):
        row = {"group": tag, args.knob: knob, "replicas": len(members),
               "seconds": statistics.fmean(m["seconds"] for m in members)}
        for q in args.quantity:
            devs = [m[q + "_deviation"] for m in members]
            row[q + "_deviation"] = statistics.fmean(devs)
            row[q + "_deviation_err"] = (statistics.stdev(devs) / math.sqrt(len(devs))
                                         if len(devs) > 1 else float("nan"))
            if row[q + "_deviation"] > 0:
                series.setdefault(f"{q} ({tag})", []).append(
                    (row["seconds"], row[q + "_deviation"], f"{args.knob}={knob:g}"))
        out.append(row)
    return out, series


if __name__ == "__main__":
    main()
