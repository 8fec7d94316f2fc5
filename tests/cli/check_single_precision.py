"""A plain H5MD file whose positions are 32-bit floats (as other tools write them): the h5md
source says in run.log that contacts found from them by distance are coarser than the
contact tolerance; the same file with doubles says nothing. Before, packing's z of this FCC
crystal read 4 for 12 without a word."""
import json
import os
import subprocess
import sys

import numpy as np

from foreign_h5md import write_h5md

exe, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)


def fcc(cells):
    """FCC of touching spheres of radius 0.5 (cube side sqrt 2), periodic box."""
    a = np.sqrt(2.0)
    basis = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    sites = [(np.array([i, j, k]) + b) * a for i in range(cells) for j in range(cells)
             for k in range(cells) for b in basis]
    return np.array(sites) + 0.25, cells * a


def warnings(dtype):
    x, side = fcc(4)
    path = os.path.join(work, f"fcc_{dtype}.h5")
    write_h5md(path, x.astype(dtype), [side] * 3, "periodic", "check_single_precision.py")
    pipeline = {"name": "single_precision", "seed": 1,
                "source": {"plugin": "h5md", "params": {"file": path}},
                "analyzers": [{"plugin": "packing"}],
                "output": {"dir": os.path.join(work, f"out_{dtype}"), "save_frames": False}}
    spec = os.path.join(work, f"{dtype}.json")
    with open(spec, "w") as f:
        json.dump(pipeline, f)
    run = subprocess.run([exe, spec, "--quiet", "--no-report", "--overwrite"], capture_output=True,
                         text=True)
    if run.returncode != 0:
        sys.exit(f"{dtype}: exit {run.returncode}: {run.stderr}")
    with open(os.path.join(work, f"out_{dtype}", "run.log")) as f:
        return [line for line in f if "bit floats" in line]


single, double = warnings("f4"), warnings("f8")
assert len(single) == 1 and "positions stored as 32-bit floats" in single[0] \
    and "coarser than the contact_tolerance 1e-09" in single[0], single
assert not double, double
print("32-bit positions said in run.log:", single[0].strip())
