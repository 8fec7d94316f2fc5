"""scripts/row_counts.py on hand-built stacks of rows in the paper's box (width 20, radius
0.1 + 1/sqrt(2)): rows of 12 and 11 in their pockets are counted exactly; a row with a disk
taken out counts one disk less; the excluded base and surface rows do not count; two rows
run together are counted apart as unsplit, not as a row; a 3D file is refused with a line
naming it."""
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

script = sys.argv[1]
r = 0.1 + 1 / math.sqrt(2)
d = 2 * r
width = 20.0


def stack(rows, missing=()):
    """Rows alternating 12 (against the left wall) and 11 (in their pockets), bottom up;
    `missing` lists (row, index) of disks left out."""
    disks = []
    for i in range(rows):
        n, x0 = (12, r) if i % 2 == 0 else (11, r + d / 2)
        disks += [(x0 + k * d, r + i * d * math.sqrt(3) / 2) for k in range(n) if (i, k) not in missing]
    return np.array(disks)


def write(path, frames, dims=2):
    """A frames.h5 with what the script reads, in the layout granpipe writes (file format 2.0:
    the radius an H5MD element of /particles/all); frames of one file hold as many disks."""
    pos = np.array(frames)
    if dims == 3:
        pos = np.concatenate([pos, np.zeros(pos.shape[:2] + (1,))], axis=2)
    with h5py.File(path, "w") as f:
        f["particles/all/position/value"] = pos
        f["particles/all/radius/value"] = np.full(pos.shape[:2], r)
        f["particles/all/box/edges/value"] = np.tile([width, 100.0, 1.0][:dims], (len(frames), 1))


def run(path):
    return subprocess.run([sys.executable, script, path], capture_output=True, text=True)


failures = []
with tempfile.TemporaryDirectory() as out:
    # 20 rows, 13 counted (rows 3 to 15; 3 at the bottom and 4 at the top left out): 6 of 12, 7 of 11.
    whole = os.path.join(out, "whole.h5")
    write(whole, [stack(20), stack(20)])
    res = run(whole)
    want = f"rows 26 mean {(6 * 12 + 7 * 11) / 13:.3f} shares 11:{7 / 13:.3f} 12:{6 / 13:.3f} unsplit 0"
    if res.returncode != 0 or want not in res.stdout:
        failures.append(f"whole stack: expected '{want}', got {res.stdout!r} {res.stderr!r}")

    # One disk out of a counted 11-row (row 5) in one frame of two; the others out of rows 0
    # and 1, which are not counted.
    holed = os.path.join(out, "holed.h5")
    write(holed, [stack(20, missing={(5, 4), (0, 3)}), stack(20, missing={(0, 3), (1, 0)})])
    res = run(holed)
    want = f"mean {(12 * 12 + 13 * 11 + 10) / 26:.3f} shares 10:{1 / 26:.3f} 11:{13 / 26:.3f} 12:{12 / 26:.3f}"
    if res.returncode != 0 or want not in res.stdout:
        failures.append(f"holed stack: expected '{want}', got {res.stdout!r} {res.stderr!r}")

    # Row 8 lowered onto row 7: one cluster of 23 disks, no row; counted apart, not averaged.
    merged_frame = stack(20)
    merged_frame[merged_frame[:, 1] > r + 7.5 * d * math.sqrt(3) / 2] -= [0, 0.9 * d * math.sqrt(3) / 2]
    merged = os.path.join(out, "merged.h5")
    write(merged, [merged_frame])
    res = run(merged)
    want = f"rows 11 mean {(5 * 12 + 6 * 11) / 11:.3f} shares 11:{6 / 11:.3f} 12:{5 / 11:.3f} unsplit 1"
    if res.returncode != 0 or want not in res.stdout:
        failures.append(f"merged rows: expected '{want}', got {res.stdout!r} {res.stderr!r}")

    flat = os.path.join(out, "three_d.h5")
    write(flat, [stack(20)], dims=3)
    res = run(flat)
    if res.returncode != 2 or f"{flat}: particles/all/position: expected 2D positions" not in res.stderr:
        failures.append(f"3D file: expected a refusal naming it, got {res.returncode} {res.stderr!r}")

for f in failures:
    print(f)
sys.exit(1 if failures else 0)
