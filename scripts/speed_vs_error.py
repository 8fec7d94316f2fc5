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
import argparse
import os

from charts import loglog_chart
from input_error import read_pipeline, refuse
from result_csv import read_table, write_csv
from speed_error import deviation_table, other_swept, pooled, value_namer


def read_points(path):
    provenance, header, rows = read_table(path)
    if not rows:
        refuse(f"{path}: expected rows of sweep points, found only a header")
    return provenance, [dict(zip(header, row)) for row in rows], header


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", help="output directory of a sweep run")
    ap.add_argument("--knob", required=True, help="swept resolution column; its smallest value is the reference")
    ap.add_argument("--time", required=True, help="column holding the run time of a point")
    ap.add_argument("--quantity", action="append", required=True, help="result column to compare (repeatable)")
    ap.add_argument("--pool", help="swept parameter (e.g. replicas) to average the deviations over")
    args = ap.parse_args()

    provenance, points, header = read_points(os.path.join(args.out, "sweep.points.csv"))
    for col in [args.knob, args.time] + args.quantity:
        if col not in header:
            refuse(f"{args.out}/sweep.points.csv: expected a column {col}, got none")
    swept = other_swept(header, args.knob)
    name_of = value_namer(read_pipeline(args.out))
    rows, series = deviation_table(points, swept, args.knob, args.time, args.quantity, name_of)
    if args.pool:
        if args.pool not in swept:
            refuse(f"{args.out}/sweep.points.csv: --pool {args.pool}: expected a swept parameter, got none")
        rows, series = pooled(rows, args.knob, args.quantity, args.pool)
    write_csv(os.path.join(args.out, "speed_vs_error.csv"),
              f"{provenance or '#'} speed against error by scripts/speed_vs_error.py",
              [list(rows[0].keys())] + [list(r.values()) for r in rows])
    loglog_chart(series, "run time of the point (s)", "|deviation from the finest point|",
             os.path.join(args.out, "speed_vs_error.svg"))
    cols = ["group", args.knob, "seconds"] + [q + "_deviation" for q in args.quantity]
    if args.pool:
        cols += [q + "_deviation_err" for q in args.quantity]
    print("  ".join(f"{c:>24}" for c in cols))
    for r in rows:
        print("  ".join(f"{r[c]:>24}" if isinstance(r[c], str) else f"{r[c]:>24.4g}" for c in cols))


if __name__ == "__main__":
    main()
