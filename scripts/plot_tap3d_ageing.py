#!/usr/bin/env python3
"""Fig. 5 of the 3D tapping paper from the tables of scripts/pool_ageing.py: A(t, t_w) against
t for each waiting time (up), and the collapse the fits of Eq. (6) give (down): A / A_inf
against x = B ln(1 + t / tau) falls on x / (1 + x) for every t_w whose fit is defined (status
0). Also A against t / t_w, where curves of a simple ageing fall on one another.

    scripts/plot_tap3d_ageing.py RUN_DIR[/pooled.compaction.ageing.csv] OUT_PREFIX [--group NAME]

reads pooled.<analyzer>.ageing.csv and the fits beside it; writes OUT_PREFIX_curves.svg,
OUT_PREFIX_scaled.svg and OUT_PREFIX_collapse.svg (the collapse only when a fit is defined).
"""
import argparse
import csv
import math
import os

from charts import curves_chart
from input_error import output_prefix, refuse

COLUMNS = {"ageing": ("group", "t_w", "t", "A"), "ageing_fits": ("group", "t_w", "A_inf", "B", "tau")}


def read_rows(path, kind):
    try:
        with open(path) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    except OSError as e:
        refuse(f"{path}: expected a table of scripts/pool_ageing.py, found none: {e.strerror}")
    missing = [c for c in COLUMNS[kind] if not rows or c not in rows[0]]
    if missing:
        refuse(f"{path}: expected columns {', '.join(COLUMNS[kind])}, found no {missing[0]}")
    return rows


def tables(source):
    ageing = source if source.endswith(".csv") else os.path.join(source, "pooled.compaction.ageing.csv")
    fits = ageing.replace(".ageing.csv", ".ageing_fits.csv")
    return read_rows(ageing, "ageing"), read_rows(fits, "ageing_fits")


def by_waiting_time(rows, group):
    curves = {}
    for r in rows:
        if r["group"] == group and float(r["t"]) > 0:
            curves.setdefault(float(r["t_w"]), []).append((float(r["t"]), float(r["A"])))
    return {t_w: sorted(points) for t_w, points in sorted(curves.items())}


def collapse(curves, fits, group):
    """{label: [(x, A / A_inf)]} for each t_w with a defined fit, and the master curve."""
    series = {}
    for r in fits:
        law = [float(r[k]) for k in ("A_inf", "B", "tau")]
        t_w = float(r["t_w"])
        fitted = r.get("status", "0") == "0" and all(math.isfinite(v) for v in law)
        if r["group"] != group or not fitted or t_w not in curves:
            continue
        a_inf, b, tau = law
        series[f"t_w = {t_w:g}"] = [(b * math.log1p(t / tau), a / a_inf) for t, a in curves[t_w]]
    if series:
        top = max(x for points in series.values() for x, _ in points)
        grid = [top * k / 100 for k in range(101)]
        series["Eq. (6): x / (1 + x)"] = [(x, x / (1 + x)) for x in grid]
    return series


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source", help="the run folder pooled, or its pooled ageing table")
    parser.add_argument("prefix", help="the figures' path without _curves.svg / _collapse.svg")
    parser.add_argument("--group", default="all", help="the group of realizations (default: all)")
    args = parser.parse_args()
    is_run = not args.source.endswith(".csv")
    output_prefix(args.prefix, ["_curves.svg", "_scaled.svg", "_collapse.svg"],
                  read=[] if is_run else [args.source], runs=[args.source] if is_run else [])
    ageing, fits = tables(args.source)
    curves = by_waiting_time(ageing, args.group)
    if not curves:
        refuse(f"{args.source}: expected rows of group {args.group!r}, found none")
    curves_chart({f"t_w = {t_w:g}": points for t_w, points in curves.items()}, "taps t since t_w",
                 "A(t, t_w) (R²)", args.prefix + "_curves.svg", log_x=True)
    curves_chart({f"t_w = {t_w:g}": [(t / t_w, a) for t, a in points] for t_w, points in curves.items()},
                 "t / t_w", "A(t, t_w) (R²)", args.prefix + "_scaled.svg", log_x=True)
    collapsed = collapse(curves, fits, args.group)
    if collapsed:
        curves_chart(collapsed, "x = B ln(1 + t/τ)", "A / A∞", args.prefix + "_collapse.svg")
    else:
        print(f"{args.source}: no fit of Eq. (6) is defined, no collapse drawn")


if __name__ == "__main__":
    main()
