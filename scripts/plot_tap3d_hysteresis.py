#!/usr/bin/env python3
"""Fig. 4 of the 3D tapping paper from kept tables: <Phi^c> at the end of each step of the
ramps of sqrt(epsilon) (the by_leg table of tap3d_hysteresis.json, one line per leg) against
sqrt(epsilon), with the steady states as black squares: those of tap3d_steady_states.json (its
sweep.points.csv, <Phi^c> at the last tap) or of scripts/tap3d_steady_table.py (<Phi^c> over
taps 3000-4000, the paper's average).

    scripts/plot_tap3d_hysteresis.py docs/data/tap3d_hysteresis.by_leg.csv \\
        docs/data/tap3d_steady_states.sweep.points.csv docs/img/tap3d_fig4.svg
    scripts/plot_tap3d_hysteresis.py docs/data/tap3d_hysteresis_paper.by_leg.csv \\
        docs/data/tap3d_steady_paper.csv docs/img/tap3d_fig4_paper.svg
"""
import math
import sys

from charts import line_chart
from input_error import refuse, require_outputs
from pool_replicas import BRANCHES
from result_csv import read_table


def column(path, header, *names):
    """The index of the first of `names` the header has."""
    for name in names:
        if name in header:
            return header.index(name)
    refuse(f"{path}: expected a column {' or '.join(names)}, found {header[:4]}...")


def main(by_leg, points, out):
    require_outputs([out], read=[by_leg, points])
    _, header, rows = read_table(by_leg)
    leg, eps = column(by_leg, header, "branch"), column(by_leg, header, "epsilon")
    phi, err = column(by_leg, header, "phi_c"), column(by_leg, header, "phi_c_err")
    series = {}
    for r in rows:
        name = f"{int(r[leg])}: {BRANCHES.get(int(r[leg]), 'leg')}"
        series.setdefault(name, []).append((math.sqrt(r[eps]), r[phi], r[err]))
    _, pheader, prow = read_table(points)
    peps = column(points, pheader, "source.params.epsilon", "epsilon")
    pphi = column(points, pheader, "stereology.phi_c_last", "phi_c_taps_3000_4000")
    reference = [(math.sqrt(r[peps]), r[pphi], math.nan) for r in prow]
    line_chart(series, reference, "√ε", "⟨Φ^c⟩ at the end of each step", out,
               reference_label="after T taps at constant ε, each from the deposition")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        refuse("usage: plot_tap3d_hysteresis.py BY_LEG.csv SWEEP_POINTS.csv OUT.svg")
    main(*sys.argv[1:])
