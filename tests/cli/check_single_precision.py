"""A plain H5MD file whose positions or radii are 32-bit floats (as other tools write them):
the h5md source says in run.log that contacts found from them by distance are coarser than
the contact tolerance; the same file with doubles says nothing. Before, packing's z of this
FCC crystal read 4 for 12 without a word (positions), and radii of 0.7 stored as 0.69999999
missed every contact."""
import json
import os
import subprocess
import sys

import numpy as np

from foreign_h5md import write_h5md

exe, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)


def fcc(cells, radius):
    """FCC of touching spheres of this radius (cube side 2 sqrt 2 radius), periodic box."""
    a = 2.0 * np.sqrt(2.0) * radius
    basis = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    sites = [(np.array([i, j, k]) + b) * a for i in range(cells) for j in range(cells)
             for k in range(cells) for b in basis]
    return np.array(sites) + 0.25, cells * a


def warnings(dtype, radius_dtype=None):
    """run.log's lines on float precision for positions stored as dtype and, when given,
    radii of 0.7 stored as radius_dtype."""
    x, side = fcc(4, 0.7 if radius_dtype else 0.5)
    radius = np.full(len(x), 0.7, dtype=radius_dtype) if radius_dtype else None
    name = f"{dtype}_{radius_dtype}"
    path = os.path.join(work, f"fcc_{name}.h5")
    write_h5md(path, x.astype(dtype), [side] * 3, "periodic", "check_single_precision.py",
               radius)
    pipeline = {"name": "single_precision", "seed": 1,
                "source": {"plugin": "h5md", "params": {"file": path}},
                "analyzers": [{"plugin": "packing"}],
                "output": {"dir": os.path.join(work, f"out_{name}"), "save_frames": False}}
    spec = os.path.join(work, f"{name}.json")
    with open(spec, "w") as f:
        json.dump(pipeline, f)
    run = subprocess.run([exe, spec, "--quiet", "--no-report", "--overwrite"], capture_output=True,
                         text=True)
    if run.returncode != 0:
        sys.exit(f"{name}: exit {run.returncode}: {run.stderr}")
    with open(os.path.join(work, f"out_{name}", "run.log")) as f:
        return [line for line in f if "bit floats" in line]


single, double = warnings("f4"), warnings("f8")
assert len(single) == 1 and "positions stored as 32-bit floats" in single[0] \
    and "coarser than the contact_tolerance 1e-09" in single[0], single
assert not double, double
single_radii, double_radii = warnings("f8", "f4"), warnings("f8", "f8")
assert len(single_radii) == 1 and "radii stored as 32-bit floats" in single_radii[0] \
    and "a radius is known to" in single_radii[0], single_radii
assert not double_radii, double_radii
print("32-bit positions said in run.log:", single[0].strip())
print("32-bit radii said in run.log:", single_radii[0].strip())
