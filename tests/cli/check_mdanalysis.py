#!/usr/bin/env python3
"""check_mdanalysis.py FRAMES_H5

MDAnalysis's H5MD reader opens a granpipe frames.h5 (which once failed on `unit`
attributes holding dimension names) and reads the positions h5py reads. Exit 77 (skipped)
when MDAnalysis is not installed.
"""
import sys

try:
    from MDAnalysis.coordinates.H5MD import H5MDReader
except ImportError:
    print("skipped: MDAnalysis is not installed (Debian: apt-get install python3-mdanalysis)")
    sys.exit(77)
import h5py
import numpy as np

path = sys.argv[1]
with h5py.File(path, "r") as f:
    expected = f["particles/all/position/value"][:]
    edges = f["particles/all/box/edges/value"][:]
# H5MD carries no topology MDAnalysis can read: its H5MD reader, as Universe(topology,
# "frames.h5") uses it. granpipe writes no unit strings (its units are the inputs'), hence
# nothing to convert.
frames = H5MDReader(path, convert_units=False)
assert frames.n_frames == len(expected), f"{frames.n_frames} frames, h5py reads {len(expected)}"
assert frames.n_atoms == expected.shape[1], f"{frames.n_atoms} particles, h5py reads {expected.shape[1]}"
for t, ts in enumerate(frames):
    # MDAnalysis keeps float32 coordinates.
    np.testing.assert_allclose(ts.positions, expected[t], rtol=1e-6, atol=1e-6 * np.abs(expected[t]).max())
    # MDAnalysis 2.4 takes box/edges only as a D x D matrix, not as H5MD's vector of a
    # rectangular box that granpipe writes: it sees no box then (docs/file-format.md).
    if ts.dimensions is not None:
        np.testing.assert_allclose(ts.dimensions[:3], edges[t], rtol=1e-6)
print(f"MDAnalysis read {frames.n_frames} frame(s) of {frames.n_atoms} particles as h5py does")
