"""H5MD files as another tool writes them (h5py, no granpipe group), for the tests that read
such files: one frame at step 0, or several from a first step on (time = step)."""
import h5py
import numpy as np


def write_h5md(path, positions, edges, boundary, creator, radius=None, first_step=0):
    """positions [N][3] (one frame) or [T][N][3] (T frames, steps from first_step on, time =
    step), stored in their own dtype (a float32 array stays 32-bit); a box of these three
    edges, every side `boundary` ("periodic" or "none"); radii [N] when given."""
    positions = np.asarray(positions)
    frames = positions if positions.ndim == 3 else positions[None]
    steps = np.arange(first_step, first_step + len(frames), dtype="i8")
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
        elements = [("position", frames)]
        if radius is not None:
            elements.append(("radius", np.repeat(np.asarray(radius)[None], len(frames), axis=0)))
        for name, value in elements:
            element = group.create_group(name)
            element.create_dataset("step", data=steps)
            element.create_dataset("time", data=steps.astype(float))
            element.create_dataset("value", data=value)
