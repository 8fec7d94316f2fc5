"""Writes data-samples/two_spheres.h5: the start frame of the head-on collision of
pipelines/dem_speed_vs_error.json, as a plain H5MD 1.1 file (granpipe reads any H5MD file).

Two spheres of radius 0.5 (species 0) on the x axis, 0.02 apart (centres at x = 4.49 and
5.51, y = z = 5), approaching each other at 0.5 each (relative speed 1), in a closed box
[0, 10]^3 whose walls they never reach; time 0, step 0.

    /usr/bin/python3 data-samples/make_two_spheres.py data-samples/two_spheres.h5
"""
import sys

import h5py
import numpy as np


def element(group, name, value):
    """A time-dependent H5MD element with one sample at step 0, time 0."""
    e = group.create_group(name)
    e.create_dataset("step", data=np.array([0], dtype="i8"))
    e.create_dataset("time", data=np.array([0.0]))
    e.create_dataset("value", data=np.array([value]))


def main(path):
    with h5py.File(path, "w") as f:
        h5md = f.create_group("h5md")
        h5md.attrs["version"] = np.array([1, 1], dtype="i4")
        h5md.create_group("author").attrs["name"] = "granpipe"
        creator = h5md.create_group("creator")
        creator.attrs["name"] = "data-samples/make_two_spheres.py"
        creator.attrs["version"] = "1"
        particles = f.create_group("particles/all")
        box = particles.create_group("box")
        box.attrs["dimension"] = 3
        box.attrs["boundary"] = np.array([b"none"] * 3, dtype="S8")
        box.create_dataset("edges", data=np.array([10.0, 10.0, 10.0]))
        element(particles, "position", np.array([[4.49, 5.0, 5.0], [5.51, 5.0, 5.0]]))
        element(particles, "velocity", np.array([[0.5, 0.0, 0.0], [-0.5, 0.0, 0.0]]))
        element(particles, "radius", np.array([0.5, 0.5]))
        element(particles, "species", np.array([0, 0], dtype="i4"))


if __name__ == "__main__":
    main(sys.argv[1])
