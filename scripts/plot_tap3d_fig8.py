#!/usr/bin/env python3
"""Fig. 8 of the 3D tapping paper from runs with the `stereology` analyzer between walls: the
lateral and central packing-fraction increases over the initial packing, delta_lateral and
delta_central, against the number of taps (log scale), one line per run; and a CSV of both at
the taps of a logarithmic schedule.

usage: plot_tap3d_fig8.py RUN_DIR[=LABEL] [RUN_DIR[=LABEL]...] OUT_PREFIX
writes OUT_PREFIX_lateral.svg, OUT_PREFIX_central.svg and OUT_PREFIX.csv; a line is named
LABEL, else by its pipeline's epsilon, else by its pipeline's name"""
import csv
import os
import sys

from charts import curves_chart
from input_error import labelled_run, output_prefix, refuse
from result_csv import read_table

TABLE_TAPS = (1, 10, 100, 1000, 4000)  # the CSV's rows: taps a decade apart, and the paper's last


def line(argument):
    """(label, [(tap, delta_lateral, delta_central)]) of one run, tap 0 left out (log axis)."""
    run, _, label = labelled_run(argument)
    path = os.path.join(run, "stereology.per_frame.csv")
    if not os.path.exists(path):
        refuse(f"{path}: expected the stereology table of a single run, found none")
    _, header, rows = read_table(path)
    for column in ("tap", "delta_lateral", "delta_central"):
        if column not in header:
            refuse(f"{path}: expected a column {column}, found {header}")
    tap, lat, cen = (header.index(c) for c in ("tap", "delta_lateral", "delta_central"))
    return label, [(r[tap], r[lat], r[cen]) for r in rows if r[tap] > 0]


def table_rows(label, points):
    """The last point at or below each tap of TABLE_TAPS, each point once (a run that ended
    earlier stops at its last)."""
    chosen = []
    for want in TABLE_TAPS:
        below = [p for p in points if p[0] <= want]
        if below and below[-1] not in chosen:
            chosen.append(below[-1])
    return [[label, *p] for p in chosen]


def main(runs, prefix):
    output_prefix(prefix, ["_lateral.svg", "_central.svg", ".csv"], runs=[a.partition("=")[0] for a in runs])
    lines = [line(run) for run in runs]
    for k, suffix, ylabel in ((1, "lateral", "δΦ_lateral"), (2, "central", "δΦ_central")):
        series = {label: [(p[0], p[k]) for p in points] for label, points in lines}
        curves_chart(series, "taps t", ylabel, f"{prefix}_{suffix}.svg", log_x=True)
    with open(f"{prefix}.csv", "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["run", "tap", "delta_lateral", "delta_central"])
        for label, points in lines:
            out.writerows(table_rows(label, points))


if __name__ == "__main__":
    if len(sys.argv) < 3:
        refuse("usage: plot_tap3d_fig8.py RUN_DIR[=LABEL] [RUN_DIR[=LABEL]...] OUT_PREFIX")
    main(sys.argv[1:-1], sys.argv[-1])
