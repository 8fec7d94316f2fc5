#!/usr/bin/python3
"""Checks frames.h5 files against H5MD 1.1 and docs/file-format.md, with h5py.

h5py is an independent reader: if it sees the layout the documentation describes, so
will MDAnalysis, pyh5md and other H5MD tools.

usage: h5md_layout_check.py [--fixture FILE]... [FILE]...

Every FILE is checked for its layout. A --fixture FILE is also checked for the values
tests/python/write_sample_frames.cpp writes (position = frame + 0.01 particle +
0.001 axis; frame k has k + 1 contacts), which catches transposed or shifted arrays.
"""
import argparse
import json
import sys

import h5py
import numpy as np


class LayoutError(Exception):
    pass


def require(condition, where, message):
    if not condition:
        raise LayoutError(f"{where}: {message}")


def fixed_string_attribute(obj, name):
    """H5MD asks for fixed-length strings in its metadata attributes."""
    where = f"{obj.name}@{name}"
    require(name in obj.attrs, where, "missing")
    dtype = obj.attrs.get_id(name).dtype
    require(dtype.kind == "S", where, f"expected a fixed-length string, got dtype {dtype}")
    value = obj.attrs[name]
    decode = lambda b: b.decode() if isinstance(b, bytes) else str(b)
    return [decode(v) for v in value] if isinstance(value, np.ndarray) else decode(value)


def dataset(group, name, shape, kind, size=8):
    path = f"{group.name}/{name}"
    require(name in group, path, "missing")
    ds = group[name]
    require(isinstance(ds, h5py.Dataset), path, "expected a dataset")
    require(ds.shape == shape, path, f"expected shape {shape}, got {ds.shape}")
    require(ds.dtype.kind == kind and ds.dtype.itemsize == size, path,
            f"expected dtype {kind}{size}, got {ds.dtype}")
    if shape:
        require(ds.maxshape[0] is None, path, "the frame axis must be unlimited")
        require(ds.chunks is not None, path, "expected a chunked dataset")
    return ds


def element(group, name, frames, item, kind, size, clock):
    """A time-dependent H5MD element whose step and time are position's (hard links)."""
    path = f"{group.name}/{name}"
    require(name in group and isinstance(group[name], h5py.Group), path,
            "expected a time-dependent element (a group)")
    e = group[name]
    step = dataset(e, "step", (frames,), "i", 8)
    time = dataset(e, "time", (frames,), "f", 8)
    if clock is not None:
        require(step == clock["step"] and time == clock["time"], path,
                "step and time must be hard links to position's")
    return dataset(e, "value", (frames,) + item, kind, size)


def enum_dataset(group, name, shape, names):
    ds = dataset(group, name, shape, "u", 1)
    mapping = h5py.check_enum_dtype(ds.dtype)
    require(mapping == names, ds.name, f"expected enumeration {names}, got {mapping}")
    return ds


def check_file(path, fixture):
    with h5py.File(path, "r") as f:  # a completed file opens normally
        h5md = f["h5md"]
        version = h5md.attrs["version"]
        require(list(version) == [1, 1] and version.dtype.kind == "i", "/h5md@version",
                f"expected integers [1, 1], got {version}")
        require(fixed_string_attribute(f["h5md/author"], "name") != "", "/h5md/author@name",
                "expected an author name")
        require(fixed_string_attribute(f["h5md/creator"], "name") == "granpipe",
                "/h5md/creator@name", "expected granpipe")
        fixed_string_attribute(f["h5md/creator"], "version")

        ext = f["granpipe"]
        require(list(ext.attrs["version"]) == [2, 0], "/granpipe@version", "expected [2, 0]")
        require(int(ext.attrs["complete"]) == 1, "/granpipe@complete",
                "expected 1 (a closed file)")
        json.loads(ext.attrs["provenance"])

        all_ = f["particles/all"]
        position = all_["position"]
        frames, n, dim = position["value"].shape
        require(dim in (2, 3), position.name, f"expected dimension 2 or 3, got {dim}")
        clock = position
        element(all_, "position", frames, (n, dim), "f", 8, None)
        steps = position["step"][:]
        require(np.all(np.diff(steps) > 0), position.name + "/step", "steps must increase")
        if "velocity" in all_:
            element(all_, "velocity", frames, (n, dim), "f", 8, clock)
        element(all_, "species", frames, (n,), "i", 4, clock)
        element(all_, "id", frames, (n,), "i", 8, clock)
        element(all_, "radius", frames, (n,), "f", 8, clock)
        if "angular_velocity" in all_:
            element(all_, "angular_velocity", frames, (n, 3 if dim == 3 else 1), "f", 8, clock)
        order = [s.decode() if isinstance(s, bytes) else s for s in ext.attrs["particle_columns"]]
        require(order[:4] == ["position", "radius", "id", "species"], "/granpipe@particle_columns",
                f"expected the required columns first, got {order}")
        for name in order:
            require(name in all_, f"{all_.name}/{name}", "listed in particle_columns, missing")
            value = all_[name]["value"]
            require(value.shape[:2] == (frames, n), value.name, "expected [frames][N]...")
            if name not in ("position", "velocity", "species", "id"):
                require("granpipe_components" in value.attrs, value.name,
                        "expected its granpipe_components attribute")
        if "observables" in f:
            for name, o in f["observables"].items():
                require(o["step"] == clock["step"] and o["time"] == clock["time"], o.name,
                        "step and time must be hard links to position's")
                require(o["value"].shape[0] == frames, o.name + "/value", "one row per frame")

        box = all_["box"]
        require(int(box.attrs["dimension"]) == dim, box.name + "@dimension", f"expected {dim}")
        boundary = fixed_string_attribute(box, "boundary")
        require(len(boundary) == dim and set(boundary) <= {"periodic", "none"},
                box.name + "@boundary", f"expected {dim} of periodic/none, got {boundary}")
        edges = element(box, "edges", frames, (dim,), "f", 8, clock)

        c = ext["container"]
        enum_dataset(c, "shape", (frames,), {"box": 0, "cylinder": 1})
        lo = dataset(c, "lo", (frames, 3), "f")
        hi = dataset(c, "hi", (frames, 3), "f")
        boundary_kinds = enum_dataset(c, "boundary", (frames, 3, 2),
                                      {"wall": 0, "periodic": 1, "open": 2})
        for name, shape in (("cylinder_radius", (frames,)), ("cylinder_center", (frames, 2)),
                            ("wall_offset", (frames, 3)), ("wall_velocity", (frames, 3))):
            dataset(c, name, shape, "f")
        require(np.array_equal(edges[:], (hi[:] - lo[:])[:, :dim]), edges.name,
                "box edges must be the container's hi - lo")
        periodic = [b == "periodic" for b in boundary]
        require(periodic == list(boundary_kinds[0, :dim, 0] == 1), box.name + "@boundary",
                "must say periodic exactly where the container is periodic")

        contact_count = None
        if "contacts" in ext:
            k = ext["contacts"]
            offset = dataset(k, "offset", (frames,), "i")[:]
            count = dataset(k, "count", (frames,), "i")[:]
            total = int(count.sum())
            require(offset[0] == 0 and np.array_equal(offset[1:], np.cumsum(count)[:-1]),
                    k.name + "/offset", "expected the running sum of count")
            for name in ("i", "j"):
                dataset(k, name, (total,), "i")
            dataset(k, "overlap", (total,), "f")
            for name in ("normal_force", "tangential_force", "point"):
                dataset(k, name, (total, dim), "f")
            contact_count = count

        if fixture:
            expected = (np.arange(frames)[:, None, None] + 0.01 * np.arange(n)[None, :, None]
                        + 0.001 * np.arange(dim)[None, None, :])
            require(np.array_equal(position["value"][:], expected), position.name + "/value",
                    "values differ from the fixture's (transposed or shifted?)")
            require(np.array_equal(steps, 10 * np.arange(frames)), position.name + "/step",
                    "expected 0, 10, 20, ...")
            require(np.array_equal(all_["id/value"][:], np.tile(np.arange(n), (frames, 1))),
                    all_.name + "/id/value", "expected ids 0..N-1 in every frame")
            if contact_count is not None:
                require(np.array_equal(contact_count, np.arange(frames) + 1),
                        "/granpipe/contacts/count", "expected k + 1 contacts in frame k")
    return frames, n, dim


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fixture", action="append", default=[],
                        help="a file from write_sample_frames (values checked too)")
    parser.add_argument("files", nargs="*", help="frames.h5 files (layout checked)")
    args = parser.parse_args()
    checks = [(p, True) for p in args.fixture] + [(p, False) for p in args.files]
    if not checks:
        parser.error("no file to check")
    failed = False
    for path, fixture in checks:
        try:
            frames, n, dim = check_file(path, fixture)
            print(f"{path}: ok ({frames} frames of {n} particles in {dim}D)")
        except (LayoutError, KeyError, OSError) as e:
            print(f"{path}: {e}", file=sys.stderr)
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
