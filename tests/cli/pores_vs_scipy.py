"""The pores analyzer against an independent computation: scipy's Delaunay (Qhull) of the
same centres, each simplex's circumradius minus R, of the simplices whose circumcentre lies
in the container (region "all": the hull's slivers along the walls have theirs far outside,
and are no pores of the packing). A crystal jittered by a fifth of a radius
(no two cells share a circumsphere, no four centres are coplanar, unlike a deposition's bottom
layer, where the two codes may split the flat slivers differently) must give the same number
of pores and the same xi histogram, bin by bin."""
import json
import os
import subprocess
import sys

import h5py
import numpy as np
from scipy.spatial import Delaunay

exe, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
bin_width, xi_max = 0.02, 2.0
pipeline = {
    "name": "pores_vs_scipy", "seed": 11,
    "source": {"plugin": "lattice",
               "params": {"lattice": "fcc", "cells": [4, 4, 4], "radius": 1.0, "boundary": "walls",
                          "jitter": 0.2}},
    "analyzers": [{"plugin": "pores", "params": {"region": "all", "bin_width": bin_width,
                                                 "xi_max": xi_max}}],
    "output": {"dir": os.path.join(work, "out")},
}
path = os.path.join(work, "pipeline.json")
with open(path, "w") as f:
    json.dump(pipeline, f)
subprocess.run([exe, path, "--quiet", "--overwrite"], check=True)

out = os.path.join(work, "out")
with h5py.File(os.path.join(out, "frames.h5"), "r") as f:
    centres = f["particles/all/position/value"][0]
    radius = float(f["particles/all/radius/value"][0][0])
    lo, hi = f["granpipe/container/lo"][0], f["granpipe/container/hi"][0]

tri = Delaunay(centres)
def thinnest_height(p):
    """Smallest distance from a vertex to its opposite face: 3 V / the largest face area."""
    volume = abs(np.linalg.det(p[1:] - p[0])) / 6.0
    faces = [np.delete(p, k, axis=0) for k in range(4)]
    area = max(np.linalg.norm(np.cross(f[1] - f[0], f[2] - f[0])) / 2.0 for f in faces)
    return 3.0 * volume / area


xi, flat = [], 0
for simplex in tri.simplices:
    p = centres[simplex]
    # Qhull keeps flat simplices where centres are coplanar (the bottom layer); the
    # analyzer drops cells thinner than its tolerance (1e-9 R), and so does this.
    if thinnest_height(p) < 1e-9 * radius:
        flat += 1
        continue
    # The circumcentre c solves 2 (p_i - p_0) . c = |p_i|^2 - |p_0|^2.
    a = 2.0 * (p[1:] - p[0])
    b = (p[1:] ** 2).sum(axis=1) - (p[0] ** 2).sum()
    c = np.linalg.solve(a, b)
    if (c >= lo).all() and (c < hi).all():
        xi.append((np.linalg.norm(c - p[0]) - radius) / radius)
xi = np.array(xi)

def table(name):
    with open(os.path.join(out, name)) as f:
        lines = [l for l in f if not l.startswith("#")]
    header = lines[0].strip().split(",")
    return [dict(zip(header, map(float, l.split(",")))) for l in lines[1:]]

scalars = {r: v for r, v in ((row["name"], row["value"]) for row in
                              [dict(zip(["name", "value"], l.split(",")[:2]))
                               for l in open(os.path.join(out, "pores.scalars.csv"))
                               if not l.startswith(("#", "name,"))])}
pores = float(scalars["pores"])
histogram = table("pores.xi_distribution.csv")
edges = np.arange(len(histogram) + 1) * bin_width
ours = np.array([row["count"] for row in histogram])
theirs, _ = np.histogram(xi, bins=edges)
# A simplex within 1e-9 of a bin edge may fall either side of it.
near_edge = np.abs(xi / bin_width - np.round(xi / bin_width)) < 1e-9 / bin_width
bad = []
if pores != len(xi):
    bad.append(f"pores: granpipe {pores:g}, scipy {len(xi)}")
if np.abs(ours - theirs).sum() > 2 * near_edge.sum():
    k = np.nonzero(ours != theirs)[0]
    bad.append(f"histogram differs in bins {k[:10]}: {ours[k[:10]]} against {theirs[k[:10]]}")
if bad:
    print("FAIL:", "; ".join(bad))
    sys.exit(1)
print(f"pores: {len(xi)} cells and their xi histogram equal scipy's Delaunay")
