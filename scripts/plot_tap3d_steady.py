#!/usr/bin/env python3
"""Figs. 3 and 4 of the 3D tapping paper from the table of scripts/tap3d_steady_table.py:
<Phi^c> after T taps against sqrt(epsilon) (Fig. 4's black squares, with the mean over the
last 1000 taps), sigma_<Z> against sqrt(epsilon) about the steady mean and about the drift,
with a least-squares line (Fig. 3, down), and, for the runs named, the power spectra of <Z>
(Fig. 3, up).

    scripts/plot_tap3d_steady.py TABLE.csv OUT_PREFIX [RUN_DIR[=LABEL] ...]

writes OUT_PREFIX_phi_c.svg, OUT_PREFIX_sigma.svg and, with runs, OUT_PREFIX_spectra.svg.
"""
import math
import os
import sys

import numpy as np

from charts import curves_chart, line_chart
from input_error import labelled_run, output_prefix, refuse
from result_csv import columns, read_table


def last_window(header):
    windows = [h for h in header if h.startswith("phi_c_taps_")]
    return windows[-1] if windows else None


def phi_c_chart(path, header, rows, out):
    root, last = columns(path, header, rows, "sqrt_epsilon", "phi_c_last")
    series = {"⟨Φ^c⟩ at the last tap": [(x, y, math.nan) for x, y in zip(root, last)]}
    window = last_window(header)
    if window:
        (means,) = columns(path, header, rows, window)
        taps = window.removeprefix("phi_c_taps_").replace("_", "–")
        series[f"mean over taps {taps}"] = [(x, y, math.nan) for x, y in zip(root, means)]
    line_chart(series, [], "√ε", "⟨Φ^c⟩", out)


def sigma_chart(path, header, rows, out):
    """sigma_<Z> about the steady mean (the paper's) and about the drift, with the least-squares
    line through the second (a run still compacting inflates the first)."""
    root, sigma, about_drift = columns(path, header, rows, "sqrt_epsilon", "z_mean_sigma",
                                       "z_mean_sigma_about_drift")
    series = {"σ_⟨Z⟩ about the mean (R)": [(x, y, math.nan) for x, y in zip(root, sigma)],
              "σ_⟨Z⟩ about the drift (R)": [(x, y, math.nan) for x, y in zip(root, about_drift)]}
    if len(root) >= 2:
        slope, intercept = np.polyfit(root, about_drift, 1)
        series[f"least squares: {intercept:.4f} + {slope:.4f} √ε"] = [
            (x, intercept + slope * x, math.nan) for x in (0.0, max(root))]
    line_chart(series, [], "√ε", "σ_⟨Z⟩ (R)", out)


def spectra_chart(runs, out):
    series = {}
    for argument in runs:
        run, _, label = labelled_run(argument)
        path = os.path.join(run, "compaction.spectrum.csv")
        _, header, rows = read_table(path)
        frequency, power = columns(path, header, rows, "frequency", "z_mean")
        series[label] = [(f, p) for f, p in zip(frequency, power) if f > 0 and p > 0]
    curves_chart(series, "frequency (1/taps)", "power of ⟨Z⟩ − ⟨Z⟩_SS", out, log_y=True, log_x=True)


def main(table, prefix, runs):
    output_prefix(prefix, ["_phi_c.svg", "_sigma.svg"] + (["_spectra.svg"] if runs else []),
                  read=[table], runs=[a.partition("=")[0] for a in runs])
    _, header, rows = read_table(table)
    if not rows:
        refuse(f"{table}: expected at least one run, found none")
    phi_c_chart(table, header, rows, prefix + "_phi_c.svg")
    sigma_chart(table, header, rows, prefix + "_sigma.svg")
    if runs:
        spectra_chart(runs, prefix + "_spectra.svg")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        refuse("usage: plot_tap3d_steady.py TABLE.csv OUT_PREFIX [RUN_DIR[=LABEL] ...]")
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
