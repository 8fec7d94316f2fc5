"""The pores analyzer's published voronoi_volume against an independent computation:
voro++ (Debian package voro++, its command-line tool) on the same random periodic packing,
once of equal spheres (Voronoi cells) and once of unequal ones (-r: radical, i.e. Laguerre,
cells). voro++ prints a volume with %g, six significant digits: each of granpipe's volumes
rounded so must be voro++'s, within half a unit of the sixth digit (and the volumes must sum
to the box's, to 1e-9). Exits 77 (skipped) when voro++ is not installed."""
import json
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

from foreign_h5md import write_h5md

SKIP = 77
exe, work = sys.argv[1], sys.argv[2]
voro = shutil.which("voro++")
if voro is None:
    print("voro++ not installed (apt-get install voro++): skipped")
    sys.exit(SKIP)
os.makedirs(work, exist_ok=True)
side = 10.0


def random_spheres(n, radii, seed):
    """Random sequential addition of spheres of the given radius range, periodic cube."""
    rng = np.random.default_rng(seed)
    x, r = np.empty((0, 3)), np.empty(0)
    while len(r) < n:
        p, rp = rng.uniform(0.0, side, 3), rng.uniform(*radii)
        d = x - p
        d -= side * np.round(d / side)
        if np.all(np.linalg.norm(d, axis=1) >= r + rp):
            x, r = np.vstack([x, p]), np.append(r, rp)
    return x, r


def granpipe_volumes(name, x, r):
    write_h5md(os.path.join(work, name + ".h5"), x, [side] * 3, "periodic", "pores_vs_voro.py",
               radius=r)
    out = os.path.join(work, "out_" + name)
    pipeline = {"name": "pores_vs_voro", "seed": 1,
                "source": {"plugin": "h5md", "params": {"file": os.path.join(work, name + ".h5")}},
                "analyzers": [{"plugin": "pores"}], "output": {"dir": out}}
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(pipeline, f)
    subprocess.run([exe, path, "--quiet", "--overwrite"], check=True)
    with h5py.File(os.path.join(out, "frames.h5"), "r") as f:
        return f["particles/all/voronoi_volume/value"][0]


def voro_volumes(name, x, r, radical):
    path = os.path.join(work, name + ".txt")
    with open(path, "w") as f:
        for i, p in enumerate(x):
            f.write(f"{i} {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}" +
                    (f" {r[i]:.17g}\n" if radical else "\n"))
    subprocess.run([voro, "-p", "-o", *(["-r"] if radical else []), "-c", "%i %v",
                    "0", str(side), "0", str(side), "0", str(side), path], check=True)
    volumes = np.full(len(x), np.nan)
    for line in open(path + ".vol"):
        i, v = line.split()
        volumes[int(i)] = float(v)
    return volumes


bad, worst = [], 0.0
for name, radii, radical in (("equal", (0.5, 0.5), False), ("unequal", (0.3, 0.6), True)):
    x, r = random_spheres(400, radii, seed=5)
    ours, theirs = granpipe_volumes(name, x, r), voro_volumes(name, x, r, radical)
    half_digit = 0.5 * 10.0 ** (np.floor(np.log10(np.abs(theirs))) - 5)
    off = np.abs(ours - theirs) > half_digit * (1 + 1e-9)
    worst = max(worst, np.nanmax(np.abs(ours / theirs - 1.0)))
    if off.any() or np.isnan(theirs).any():
        k = np.nonzero(off)[0][:5]
        bad.append(f"{name}: particles {k}: granpipe {ours[k]}, voro++ {theirs[k]}")
    if abs(ours.sum() / side**3 - 1.0) > 1e-9:
        bad.append(f"{name}: volumes sum to {ours.sum():.12g}, the box is {side**3:g}")
if bad:
    print("FAIL:", "; ".join(bad))
    sys.exit(1)
print("voronoi_volume equals voro++'s volumes (-p, and -r for unequal radii) to its 6 printed "
      f"digits (largest relative difference {worst:.1e})")
