"""Writes small H5MD files the way another tool would (h5py, no granpipe group): one
with two overlapping particles, two with a NaN position (in the first particle, the one
minimum and maximum meet first, and in another)."""
import sys

import numpy as np

from foreign_h5md import write_h5md


def write(path, positions):
    write_h5md(path, np.array(positions, dtype="f8"), [10.0] * 3, "none", "make_bad_particles.py")


out = sys.argv[1]
write(f"{out}/overlapping.h5", [[2.0, 2.0, 2.0], [2.5, 2.0, 2.0], [6.0, 6.0, 6.0]])
write(f"{out}/nan.h5", [[2.0, 2.0, 2.0], [float("nan"), 5.0, 5.0]])
write(f"{out}/nan_first.h5", [[float("nan"), 2.0, 2.0], [5.0, 5.0, 5.0]])
