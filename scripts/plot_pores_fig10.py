#!/usr/bin/env python3
"""Fig. 10 of the 3D tapping paper from a run of pores_compaction.json (results.h5, or the
results.partial.h5 of a run stopped early): xi^3 P(xi) and rho_v(v) of the packing after
the taps asked for (the saved frame nearest each), and a table per frame: nu = <xi^3>, the
part of nu below the octahedral size xi_O = sqrt(2) - 1 and above it, <Phi^c>.

usage: plot_pores_fig10.py RESULTS.h5 OUT_PREFIX [TAP...]   (taps: 0 1 4 10 30 100 300 1000 4000)
writes OUT_PREFIX_xi3P.svg, OUT_PREFIX_rho_v.svg and OUT_PREFIX.csv"""
import math
import os
import sys

import h5py
import numpy as np

from charts import curves_chart
from input_error import output_prefix, refuse

XI_O = math.sqrt(2.0) - 1.0


def read(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        refuse(f"{path}: expected the results of a granpipe run (HDF5), found none: {e}")
    try:
        xi = {k: f[f"pores/frame_xi/{k}"][:] for k in ("step", "xi", "P", "xi3_P")}
        v = {k: f[f"pores/frame_v/{k}"][:] for k in ("step", "v", "rho_v")}
        phi = dict(zip(f["stereology/per_frame/step"][:], f["stereology/per_frame/phi_c"][:]))
    except KeyError as e:
        refuse(f"{path}: expected the pores analyzer's frame_xi and frame_v tables and stereology's "
               f"per_frame (pores_compaction.json), found no {e}")
    return xi, v, phi


def nearest_steps(steps, taps):
    have = sorted(set(int(s) for s in steps))
    return sorted({min(have, key=lambda s: abs(s - t)) for t in taps})


def main(path, prefix, taps):
    output_prefix(prefix, ["_xi3P.svg", "_rho_v.svg", ".csv"], read=[path],
                  runs=[os.path.dirname(path) or "."])
    xi, v, phi = read(path)
    chosen = nearest_steps(xi["step"], taps)
    curves_xi, curves_v, rows = {}, {}, []
    for s in chosen:
        m = xi["step"] == s
        x, x3p = xi["xi"][m], xi["xi3_P"][m]
        width = x[1] - x[0]
        small = float(np.sum(x3p[x < XI_O]) * width)
        nu = float(np.sum(x3p) * width)
        rows.append((s, nu, small, nu - small, phi.get(s, math.nan)))
        curves_xi[f"t = {s}"] = list(zip(x, x3p))
        mv = v["step"] == s
        curves_v[f"t = {s}"] = [(a, b) for a, b in zip(v["v"][mv], v["rho_v"][mv]) if b > 0]
    curves_chart(curves_xi, "ξ = r/R", "ξ³P(ξ)", f"{prefix}_xi3P.svg")
    curves_chart(curves_v, "v = ξ³", "ρ_v(v)", f"{prefix}_rho_v.svg", log_y=True)
    with open(f"{prefix}.csv", "w") as f:
        f.write("tap,nu,nu_below_xi_O,nu_above_xi_O,phi_c\n")
        for r in rows:
            f.write(",".join(f"{x:.6g}" for x in r) + "\n")


def tap_of(argument):
    try:
        return int(argument)
    except ValueError:
        refuse(f"TAP {argument!r}: expected a whole number of taps (usage: plot_pores_fig10.py "
               "RESULTS.h5 OUT_PREFIX [TAP...])")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        refuse("usage: plot_pores_fig10.py RESULTS.h5 OUT_PREFIX [TAP...]")
    taps = [tap_of(t) for t in sys.argv[3:]] or [0, 1, 4, 10, 30, 100, 300, 1000, 4000]
    main(sys.argv[1], sys.argv[2], taps)
