#!/usr/bin/env python3
"""Pools per-point tables over independent replicas of a sweep (the paper's Fig. 8: "averages
over 5 independent simulations").

Each replica is a sweep point that differs from the others only in the --over parameter
(default source.params.replica). For every group of points that share all other swept
parameters, rows of the table with the same key (default: branch and time, the by_ramp
tables) are pooled: each quantity q (a column with a q_err partner) becomes the mean of the
replica means, with the standard error across replicas (the honest error: frames of one run
are correlated), or the run's own error where only one replica has the row. `frames` adds up,
and `replicas` counts them. The table `points` stands for the scalars of each point (its row of
sweep.points.csv), pooled with no key: the steady state of a constant-amplitude sweep run
with several replicas per amplitude. Writes, beside the input:

  pooled.<table>.csv    one row per group and key
  pooled.<table>.svg    with --plot Q: Q against time, one line per branch and group (points:
                        Q against the first other swept parameter); with
                        --reference DIR, the steady-state curve of a constant-amplitude sweep
                        (DIR/sweep.points.csv: --reference-x against <analyzer>.Q) as points

    scripts/pool_replicas.py out/tap2d_annealed --table packing.by_ramp --plot phi \\
        --reference out/tap2d_arches
    scripts/pool_replicas.py out/tap2d_arches --table points
"""
import argparse
import math
import os

from charts import line_chart
from input_error import refuse
from result_csv import read_table, sweep_groups, write_csv

BRANCHES = {0: "first increase", 1: "decreasing", 2: "increasing"}


def pool(tables, keys):
    """tables: list of (file, header, rows), one per replica. Returns header and pooled rows."""
    first, header, _ = tables[0]
    for path, h, _ in tables[1:]:
        if h != header:
            refuse(f"{path}: expected the columns of the replica {first}, {header}, found {h}")
    quantities = [c for c in header if c + "_err" in header]
    index = {c: header.index(c) for c in header}
    by_key = {}
    for _, _, rows in tables:
        for row in rows:
            by_key.setdefault(tuple(row[index[k]] for k in keys), []).append(row)
    out_header = list(keys) + ["replicas", "frames"] + [c for q in quantities for c in (q, q + "_err")]
    out = []
    for key in sorted(by_key):
        rows = by_key[key]
        n = len(rows)
        line = list(key) + [n, sum(r[index["frames"]] for r in rows) if "frames" in index else math.nan]
        for q in quantities:
            values = [r[index[q]] for r in rows]
            mean = sum(values) / n
            if n > 1:
                err = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1) / n)
            else:
                err = rows[0][index[q + "_err"]]
            line += [mean, err]
        out.append(line)
    return out_header, out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", help="output directory of a sweep run")
    ap.add_argument("--table", action="append", required=True,
                    help="<analyzer>.<table>, e.g. packing.by_ramp, or points for the scalars of sweep.points.csv (repeatable)")
    ap.add_argument("--over", default="source.params.replica", help="the swept parameter that numbers the replicas")
    ap.add_argument("--key", action="append", help="key columns of a row (default: branch, time)")
    ap.add_argument("--plot", help="quantity to plot against the last key column")
    ap.add_argument("--reference", help="output directory of a constant-amplitude sweep to draw beside the plot")
    ap.add_argument("--reference-x", default="source.params.A", help="column of the reference's sweep.points.csv for x")
    args = ap.parse_args()
    points_path = os.path.join(args.out, "sweep.points.csv")
    points_provenance, header, points, others, groups = sweep_groups(args.out, args.over)

    row_of_point = {int(p[header.index("point")]): p for p in points}
    if "points" in args.table and args.plot and not others:
        refuse(f"{args.out}: --table points --plot draws against a swept parameter besides {args.over}, found none")

    for table in args.table:
        keys = [] if table == "points" else args.key or ["branch", "amplitude"]
        provenance, out_rows, out_header = "", [], None
        series = {}
        for gkey, members in sorted(groups.items()):
            tables = []
            for point in members:
                if table == "points":
                    path, provenance, h, rows = points_path, points_provenance, header, [row_of_point[point]]
                else:
                    path = os.path.join(args.out, f"point_{point:03d}.{table}.csv")
                    if not os.path.exists(path):
                        refuse(f"{path}: expected the table {table} of point {point}, found no file")
                    provenance, h, rows = read_table(path)
                tables.append((path, h, rows))
            for k in keys:
                if k not in tables[0][1]:
                    refuse(f"{tables[0][0]}: expected a key column {k}, found {tables[0][1]}")
            hdr, rows = pool(tables, keys)
            tag = ", ".join(f"{s.split('.')[-1]}={v:g}" for s, v in zip(others, gkey))
            # A point's row keeps its swept values as columns, so the pooled file is a sweep table.
            label, label_header = (list(gkey), others) if table == "points" else ([tag], ["group"]) if others else ([], [])
            out_header = label_header + hdr
            for r in rows:
                out_rows.append(label + r)
                if args.plot and args.plot in hdr:
                    y = (r[hdr.index(args.plot)], r[hdr.index(args.plot + "_err")])
                    if table == "points":
                        series.setdefault("pooled", []).append((gkey[0], *y))
                    else:
                        branch = BRANCHES.get(int(r[hdr.index("branch")]), "") if "branch" in hdr else ""
                        name = " ".join(x for x in (branch, tag) if x) or "pooled"
                        series.setdefault(name, []).append((r[hdr.index(keys[-1])], *y))
        path = os.path.join(args.out, f"pooled.{table}.csv")
        write_csv(path, f"{provenance} pooled over {args.over} by scripts/pool_replicas.py",
                  [out_header] + out_rows)
        print(f"{path}: {len(out_rows)} rows from {sum(len(m) for m in groups.values())} points")
        if args.plot and series:
            reference = []
            if args.reference:
                _, rh, rrows = read_table(os.path.join(args.reference, "sweep.points.csv"))
                column = args.plot if table == "points" else f"{table.split('.')[0]}.{args.plot}"
                if args.reference_x not in rh or column not in rh:
                    refuse(f"{args.reference}/sweep.points.csv: expected columns {args.reference_x} and {column}")
                err = rh.index(column + "_err") if column + "_err" in rh else None
                reference = [(r[rh.index(args.reference_x)], r[rh.index(column)],
                              r[err] if err is not None else math.nan) for r in rrows]
            xlabel = others[0] if table == "points" else "A" if keys[-1] == "amplitude" else keys[-1]
            line_chart(series, reference, xlabel, args.plot, os.path.join(args.out, f"pooled.{table}.svg"))


if __name__ == "__main__":
    main()
