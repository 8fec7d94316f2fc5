#!/usr/bin/env python3
"""Draws a pooled by_ramp table kept in docs/data (written by pool_replicas.py) again, without
the run's output directory: Q against A, one line per branch (and group), with the
steady-state points of a constant-amplitude run (its sweep.points.csv or pooled.points.csv)
as black squares, as pool_replicas.py --plot --reference draws it.

    scripts/plot_pooled.py docs/data/tap2d_fig8_slow.pooled.packing.by_ramp.csv --plot phi \\
        --reference docs/data/tap2d_arches_N2000.sweep.points.csv --column packing.phi \\
        --out docs/img/tap2d_fig8_phi.svg
"""
import argparse
import csv
import math

from charts import line_chart
from input_error import refuse, require_outputs
from pool_replicas import BRANCHES
from result_csv import read_table


def read_pooled(path):
    """Rows of a pooled table as dicts of strings (its group column holds text)."""
    try:
        with open(path) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    except OSError as e:
        refuse(f"{path}: expected a pooled table, found none: {e.strerror}")
    if not rows:
        refuse(f"{path}: expected rows of a pooled table, found none")
    return rows


def number(path, row, column):
    try:
        return float(row[column])
    except (KeyError, TypeError, ValueError):
        refuse(f"{path}: expected a number in column {column}, found {row.get(column)!r}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("table", help="a pooled.<analyzer>.by_ramp.csv")
    ap.add_argument("--plot", required=True, help="quantity to draw (a column with a _err partner)")
    ap.add_argument("--x", default=None, help="column for x (default: amplitude, or time in tables made before it was named)")
    ap.add_argument("--reference", help="sweep.points.csv or pooled.points.csv of a constant-amplitude run")
    ap.add_argument("--reference-x", default="source.params.A", help="column of the reference for x")
    ap.add_argument("--column", help="column of the reference for y (default: the quantity)")
    ap.add_argument("--out", required=True, help="figure to write (.svg or .png)")
    args = ap.parse_args()
    require_outputs([args.out], read=[args.table] + ([args.reference] if args.reference else []))

    rows = read_pooled(args.table)
    x = args.x or ("amplitude" if "amplitude" in rows[0] else "time")
    series = {}
    for row in rows:
        branch = BRANCHES.get(int(number(args.table, row, "branch")), "") if "branch" in row else ""
        name = " ".join(s for s in (branch, row.get("group", "")) if s) or "pooled"
        point = tuple(number(args.table, row, c) for c in (x, args.plot, args.plot + "_err"))
        series.setdefault(name, []).append(point)
    reference = []
    if args.reference:
        _, header, ref_rows = read_table(args.reference)
        column = args.column or args.plot
        for c in (args.reference_x, column):
            if c not in header:
                refuse(f"{args.reference}: expected a column {c}, found {header[:4]}...")
        err = header.index(column + "_err") if column + "_err" in header else None
        reference = [(r[header.index(args.reference_x)], r[header.index(column)],
                      r[err] if err is not None else math.nan) for r in ref_rows]
    line_chart(series, reference, "A", args.plot, args.out)
    print(f"{args.out}: {len(series)} series, {len(reference)} reference points")


if __name__ == "__main__":
    main()
