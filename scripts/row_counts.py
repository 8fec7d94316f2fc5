#!/usr/bin/env python3
"""Disks per row in layered 2D beds (docs/notes/disks2d-tap-record.md, "Widths near 20").

A layered bed is a stack of horizontal rows; its area fraction is the mean disk area per row
over the width times the row spacing, so counting rows tells which stack a bed is
(12 and 11 alternating in the paper's box) and whether rows lose disks. Rows are clusters of
centre heights, split where consecutive heights are more than --gap diameters apart; the
lowest --skip-bottom and highest --skip-top rows are left out (the base layer and the loose
surface). A cluster holding more disks than a row can (more than width / diameter) is a
disordered patch or rows not told apart, not a row: it is counted apart as `unsplit` and kept
out of the mean.

    scripts/row_counts.py out/tap2d_arches/point_003/frames.h5 [more frames.h5 ...]

prints, per file, the rows counted, the mean disks per row and the share of rows holding each
number of disks, over every frame of the file.
"""
import argparse
import sys
from collections import Counter

import h5py
import numpy as np
from input_error import refuse


def row_sizes(x_y, diameter, gap, skip_bottom, skip_top):
    """Sizes of the rows of one frame, the excluded rows left out."""
    heights = np.sort(x_y[:, 1])
    rows = np.split(heights, np.where(np.diff(heights) > gap * diameter)[0] + 1)
    kept = rows[skip_bottom:len(rows) - skip_top]
    return [len(r) for r in kept]


def count_file(path, gap, skip_bottom, skip_top):
    try:
        with h5py.File(path, "r") as f:
            positions = f["particles/all/position/value"][:]
            radii = f["particles/all/radius/value"][:]  # file format 2.0 (docs/file-format.md)
            width = f["particles/all/box/edges/value"][0][0]
    except (OSError, KeyError) as e:
        refuse(f"{path}: expected a 2D granpipe frames.h5, could not read it ({e})")
    if positions.shape[-1] != 2:
        refuse(f"{path}: particles/all/position: expected 2D positions, "
               f"found {positions.shape[-1]} components")
    sizes = []
    for frame, r in zip(positions, radii):
        sizes += row_sizes(frame, 2.0 * r.mean(), gap, skip_bottom, skip_top)
    most = int(width / (2.0 * radii.mean()))
    rows = [s for s in sizes if s <= most]
    return rows, len(sizes) - len(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="+", help="frames.h5 files of 2D runs")
    parser.add_argument("--gap", type=float, default=0.4,
                        help="split rows where heights differ by more (diameters)")
    parser.add_argument("--skip-bottom", type=int, default=3)
    parser.add_argument("--skip-top", type=int, default=4)
    args = parser.parse_args()
    for path in args.files:
        rows, unsplit = count_file(path, args.gap, args.skip_bottom, args.skip_top)
        if not rows:
            print(f"{path}: no rows (too few rows, or no layers)")
            continue
        shares = " ".join(f"{n}:{c / len(rows):.3f}" for n, c in sorted(Counter(rows).items()))
        print(f"{path}: rows {len(rows)} mean {np.mean(rows):.3f} shares {shares} unsplit {unsplit}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
