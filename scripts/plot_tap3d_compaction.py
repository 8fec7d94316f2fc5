#!/usr/bin/env python3
"""Fig. 2 and the fit table of the 3D tapping paper from runs with the `compaction` analyzer:
Phi_b, <Phi^c> and <Z> against the number of taps, log and linear, with the Eq. (3) and (4)
fits dotted; and a CSV of the fitted parameters, the steady states and the spectrum slopes.
A run is a sweep over epsilon (tap3d_compaction.json: one line per point) or a single run
(one line, named by its epsilon, or by its pipeline's name when it has none - a reprocessing
of saved frames); RUN_DIR=LABEL names a single run's line LABEL (a reprocessing, e.g. of a run
split over sessions: "reprocess_eps0.15=ε = 0.15").

usage: plot_tap3d_compaction.py RUN_DIR[=LABEL] [RUN_DIR[=LABEL]...] OUT_PREFIX
writes OUT_PREFIX_phi_b.svg, OUT_PREFIX_phi_c.svg, OUT_PREFIX_z.svg and OUT_PREFIX.csv"""
import csv
import math
import os
import sys

from charts import compaction_chart
from input_error import labelled_run, output_prefix, refuse
from result_csv import read_table

# The laws of the paper: Eq. (3) for a packing fraction, Eq. (4) for <Z>.
def eq3(t, p):
    return p["X_inf"] - p["dX_inf"] / (1.0 + p["B"] * math.log(1.0 + t / p["tau"]))


def eq4(t, p):
    g = p["B"] * math.log(1.0 + t / p["tau"])
    return p["Z_inf"] * (1.0 + g) / (p["Z_inf"] / p["Z_0"] + g)


SERIES = [  # (column of per_frame, fit table, law, axis label, file suffix)
    ("phi_b", "eq3_phi_b", eq3, "bottom packing fraction Φ_b", "phi_b"),
    ("phi_c", "eq3_phi_c", eq3, "⟨Φ^c⟩", "phi_c"),
    ("z_mean", "eq4_z_mean", eq4, "⟨Z⟩ (R)", "z"),
]


def curves(argument):
    """[(label, epsilon or nan, path of a table by name)] of a run: each sweep point, or the run."""
    run = argument.partition("=")[0]
    if not os.path.exists(os.path.join(run, "sweep.points.csv")):
        _, pipeline, label = labelled_run(argument)
        eps = pipeline.get("source", {}).get("params", {}).get("epsilon")
        return [(label, math.nan if eps is None else eps,
                 lambda name: os.path.join(run, f"compaction.{name}.csv"))]
    _, header, points = read_table(os.path.join(run, "sweep.points.csv"))
    column = "source.params.epsilon"
    if column not in header:
        refuse(f"{run}/sweep.points.csv: expected a sweep over {column}, found {header[1:3]}...")
    return [(f"ε = {p[header.index(column)]:g}", p[header.index(column)],
             lambda name, k=int(p[0]): os.path.join(run, f"point_{k:03d}.compaction.{name}.csv"))
            for p in points]


def named_rows(path):
    """{name: (value, error)} of a table whose rows start with a name (fit parameters, scalars)."""
    try:
        with open(path) as f:
            rows = list(csv.reader(line for line in f if not line.startswith("#")))
    except OSError as e:
        refuse(f"{path}: expected a granpipe table, found none: {e.strerror}")
    try:
        return {row[0]: (float(row[1]), float(row[2])) for row in rows[1:]}
    except (ValueError, IndexError):
        refuse(f"{path}: expected rows of a name, a value and an error, found {rows[1:2]}")


def main(runs, prefix):
    output_prefix(prefix, [f"_{s[-1]}.svg" for s in SERIES] + [".csv"],
                  runs=[a.partition("=")[0] for a in runs])
    lines = [c for run in runs for c in curves(run)]
    summary = []
    for label, table, law, ylabel, suffix in SERIES:
        series, fits = {}, {}
        for name, eps, files in lines:
            _, ph, rows = read_table(files("per_frame"))
            series[name] = [(r[ph.index("tap")], r[ph.index(label)]) for r in rows]
            params = named_rows(files(table))
            values = {k: v for k, (v, _) in params.items()}
            if all(math.isfinite(v) for v in values.values()):
                fits[name] = [(t, law(t, values)) for t, _ in series[name]]
            summary += [(name, table, k, v, e) for k, (v, e) in params.items()]
        compaction_chart(series, fits, ylabel, f"{prefix}_{suffix}.svg")
    for name, eps, files in lines:
        for k, (v, e) in named_rows(files("scalars")).items():
            if k.endswith(("_ss", "_sigma")) or k.startswith(("spectrum_slope", "steady_from", "fit_")):
                summary.append((name, "steady", k, v, e))
    with open(f"{prefix}.csv", "w") as f:
        f.write("run,table,parameter,value,error\n")
        for name, table, k, v, e in summary:
            f.write(f"{name},{table},{k},{v:.6g},{e:.3g}\n")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        refuse("usage: plot_tap3d_compaction.py RUN_DIR[=LABEL] [RUN_DIR[=LABEL]...] OUT_PREFIX")
    main(sys.argv[1:-1], sys.argv[-1])
