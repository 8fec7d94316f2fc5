#!/usr/bin/env python3
"""The steady states of the 3D tapping paper's Figs. 3 and 4 at one epsilon per run, as one
table: for each analysed run (stereology and compaction over a constant-epsilon run of
tap3d_steady_states.json or tap3d_compaction.json, or its parts joined by the h5md source's
continued_in), <Phi^c> at the last tap and over windows of taps, Phi_b's and <Z>'s steady state
and sigma_<Z>, the spectrum slope of <Z>. A run still compacting has a drift in its "steady"
taps, which sigma_<Z> (about the mean, the paper's) counts as fluctuation: the table also
has <Z>'s drift, a straight line fitted over the steady taps, and the fluctuation about it.

    scripts/tap3d_steady_table.py OUT.csv RUN_DIR[=EPSILON] ...
    scripts/tap3d_steady_table.py OUT.csv --add RUN_DIR[=EPSILON] ...

--add keeps the rows OUT.csv holds (runs analysed before, whose folders may be gone) and adds
or replaces those of the runs given (a row of the same epsilon is replaced).

EPSILON is read from the run's pipeline (source.params.epsilon) when not given; a run
analysed from saved frames (the h5md source) has none, so give it there. Windows of 1000 taps
from tap 1000 on, as many as the last tap allows (the paper averages the last 1000 of 4000).
"""
import json
import math
import os
import sys

import numpy as np

from input_error import read_pipeline, refuse, require_outputs
from result_csv import columns, finite_column, read_scalars, read_table

WINDOW = 1000  # taps


def positive_number(text):
    """`text` as a finite number > 0 (epsilon: its root is taken), or None."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) and value > 0 else None


def epsilon_of(run, given):
    if given:
        eps = positive_number(given)
        if eps is None:
            refuse(f"{run}={given}: expected a finite number > 0 after '=', found {given!r}")
        return eps
    eps = read_pipeline(run).get("source", {}).get("params", {}).get("epsilon")
    if eps is None:
        refuse(f"{run}/pipeline.json: expected source.params.epsilon, found none "
               "(a run analysed from saved frames: give it as RUN_DIR=EPSILON)")
    if isinstance(eps, bool) or positive_number(eps) is None:
        refuse(f"{run}/pipeline.json: source.params.epsilon: expected a finite number > 0, "
               f"found {json.dumps(eps)}")
    return float(eps)


def window_means(run):
    """<Phi^c> over [1000, 2000), [2000, 3000), ... up to the last tap, and the last tap's."""
    path = os.path.join(run, "stereology.per_frame.csv")
    _, header, rows = read_table(path)
    taps = finite_column(path, header, rows, "tap")
    (phi,) = columns(path, header, rows, "phi_c")
    last = max(taps)
    means = []
    for start in range(WINDOW, int(last), WINDOW):
        inside = [p for t, p in zip(taps, phi) if start <= t < start + WINDOW]
        means.append(sum(inside) / len(inside) if inside else math.nan)
    last_phi = phi[taps.index(last)]
    return int(last), last_phi, means


def drift_of(run, steady_from):
    """<Z>'s least-squares slope over the taps from steady_from on, per 1000 taps, and the
    root mean square of <Z> about that line."""
    path = os.path.join(run, "compaction.per_frame.csv")
    _, header, rows = read_table(path)
    taps = finite_column(path, header, rows, "tap")
    (z_mean,) = columns(path, header, rows, "z_mean")
    steady = np.array([(t, z) for t, z in zip(taps, z_mean) if t >= steady_from])
    if len(steady) < 3:
        return math.nan, math.nan
    slope, intercept = np.polyfit(steady[:, 0], steady[:, 1], 1)
    residual = steady[:, 1] - (intercept + slope * steady[:, 0])
    return slope * WINDOW, float(np.sqrt(np.mean(residual ** 2)))


def row_of(argument):
    run, _, given = argument.partition("=")
    eps = epsilon_of(run, given)
    last, phi_last, means = window_means(run)
    c = read_scalars(os.path.join(run, "compaction.scalars.csv"))
    for name in ("phi_b_ss", "z_mean_sigma", "spectrum_slope_z_mean", "steady_from"):
        if name not in c:
            refuse(f"{run}/compaction.scalars.csv: expected {name}, found none")
    return {"epsilon": eps, "sqrt_epsilon": math.sqrt(eps), "last_tap": last,
            "phi_c_last": phi_last,
            **{f"phi_c_taps_{(k + 1) * WINDOW}_{(k + 2) * WINDOW}": m for k, m in enumerate(means)},
            "phi_b_ss": c["phi_b_ss"][0], "phi_b_ss_err": c["phi_b_ss"][1],
            "z_mean_sigma": c["z_mean_sigma"][0],
            **dict(zip(("z_mean_drift_per_1000_taps", "z_mean_sigma_about_drift"),
                       drift_of(run, c["steady_from"][0]))),
            "spectrum_slope_z_mean": c["spectrum_slope_z_mean"][0],
            "spectrum_slope_z_mean_err": c["spectrum_slope_z_mean"][1]}


def kept_rows(out):
    """With --add: the rows of the table `out` already holds (runs analysed before, whose
    folders may be gone) and its provenance, to be written again beside the new runs'."""
    provenance, header, rows = read_table(out)
    columns(out, header, rows, "epsilon")  # refuses a table of other columns
    return provenance, [dict(zip(header, r)) for r in rows]


def main(out, runs, add):
    require_outputs([out], runs=[a.partition("=")[0] for a in runs])
    provenance, rows = kept_rows(out) if add else ("", [])
    new = [row_of(a) for a in runs]
    given = {r["epsilon"] for r in new}
    rows = sorted([r for r in rows if r["epsilon"] not in given] + new, key=lambda r: r["epsilon"])
    header = []
    for r in rows:
        header += [k for k in r if k not in header]
    written = provenance + " then --add " if provenance else "# written by scripts/tap3d_steady_table.py "
    with open(out, "w") as f:
        f.write(written + " ".join(runs) + "\n")
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(f"{r.get(k, math.nan):.6g}" for k in header) + "\n")
    print(f"{out}: {len(rows)} rows")


if __name__ == "__main__":
    add = len(sys.argv) > 2 and sys.argv[2] == "--add"
    if len(sys.argv) < 3 + add:
        refuse("usage: tap3d_steady_table.py OUT.csv [--add] RUN_DIR[=EPSILON] ...")
    main(sys.argv[1], sys.argv[2 + add:], add)
