"""Writes data-samples/fcc_jitter_small.dump: the four frames of fcc_jitter_small.h5 as the
text dump LAMMPS writes with

    dump 1 all custom 1 fcc_jitter_small.dump id type x y z radius

(its default formats: the box bounds as %-1.16e, the other numbers as %g; LAMMPS ids and
types from 1), so that pipelines/reprocess_lammps_dump.json measures the same packing
through the lammps_dump source. The atom lines are in the order of the H5MD file's ids
reversed, as a LAMMPS run on several processors leaves them out of order.

    /usr/bin/python3 data-samples/make_fcc_dump.py data-samples/fcc_jitter_small.h5 \\
        data-samples/fcc_jitter_small.dump
"""
import sys

import h5py


def snapshot(step, edges, ids, species, positions, radii):
    lines = ["ITEM: TIMESTEP", f"{step}", "ITEM: NUMBER OF ATOMS", f"{len(ids)}",
             "ITEM: BOX BOUNDS pp pp pp"]
    lines += [f"{0.0:-1.16e} {edge:-1.16e}" for edge in edges]
    lines.append("ITEM: ATOMS id type x y z radius")
    for k in reversed(range(len(ids))):
        x, y, z = positions[k]
        lines.append(f"{ids[k] + 1} {species[k] + 1} {x:g} {y:g} {z:g} {radii[k]:g}")
    return "\n".join(lines) + "\n"


def main(h5_path, dump_path):
    with h5py.File(h5_path, "r") as f:
        a = f["particles/all"]
        steps = a["position/step"][()]
        edges = a["box/edges/value"][()]
        ids, species = a["id/value"][()], a["species/value"][()]
        positions, radii = a["position/value"][()], a["radius/value"][()]
    with open(dump_path, "w") as out:
        for k, step in enumerate(steps):
            out.write(snapshot(step, edges[k], ids[k], species[k], positions[k], radii[k]))


if __name__ == "__main__":
    main(*sys.argv[1:])
