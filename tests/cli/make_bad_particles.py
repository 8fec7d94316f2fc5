"""Writes small H5MD files the way another tool would (h5py, no granpipe group): one
with two overlapping particles, two with a NaN position (in the first particle, the one
minimum and maximum meet first, and in another)."""
import sys

import h5py
import numpy as np


def write(path, positions):
    with h5py.File(path, "w") as f:
        h5md = f.create_group("h5md")
        h5md.attrs["version"] = np.array([1, 1], dtype="i4")
        h5md.create_group("author").attrs["name"] = "test"
        creator = h5md.create_group("creator")
        creator.attrs["name"] = "make_bad_particles.py"
        creator.attrs["version"] = "1"
        group = f.create_group("particles/all")
        box = group.create_group("box")
        box.attrs["dimension"] = 3
        box.attrs["boundary"] = np.array([b"none"] * 3, dtype="S8")
        box.create_dataset("edges", data=np.array([10.0, 10.0, 10.0]))
        position = group.create_group("position")
        position.create_dataset("step", data=np.array([0], dtype="i8"))
        position.create_dataset("time", data=np.array([0.0]))
        position.create_dataset("value", data=np.array([positions], dtype="f8"))


out = sys.argv[1]
write(f"{out}/overlapping.h5", [[2.0, 2.0, 2.0], [2.5, 2.0, 2.0], [6.0, 6.0, 6.0]])
write(f"{out}/nan.h5", [[2.0, 2.0, 2.0], [float("nan"), 5.0, 5.0]])
write(f"{out}/nan_first.h5", [[float("nan"), 2.0, 2.0], [5.0, 5.0, 5.0]])
