"""H5MD files as another tool writes them (h5py, no granpipe group), for the tests that read
such files: one frame, step 0, time 0."""
import h5py
import numpy as np


def write_h5md(path, positions, edges, boundary, creator, radius=None):
    """positions [N][3], stored in their own dtype (a float32 array stays 32-bit); a box of
    these three edges, every side `boundary` ("periodic" or "none"); radii when given."""
    with h5py.File(path, "w") as f:
        h5md = f.create_group("h5md")
        h5md.attrs["version"] = np.array([1, 1], dtype="i4")
        h5md.create_group("author").attrs["name"] = "test"
        made_by = h5md.create_group("creator")
        made_by.attrs["name"] = creator
        made_by.attrs["version"] = "1"
        group = f.create_group("particles/all")
        box = group.create_group("box")
        box.attrs["dimension"] = 3
        box.attrs["boundary"] = np.array([boundary.encode()] * 3, dtype="S8")
        box.create_dataset("edges", data=np.array(edges, dtype="f8"))
        elements = [("position", np.asarray(positions))]
        if radius is not None:
            elements.append(("radius", np.asarray(radius)))
        for name, value in elements:
            element = group.create_group(name)
            element.create_dataset("step", data=np.array([0], dtype="i8"))
            element.create_dataset("time", data=np.array([0.0]))
            element.create_dataset("value", data=value[None])
