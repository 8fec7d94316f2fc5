"""Checks a run of pipelines/lattice_packing.json end to end, through an independent reader
(h5py): every crystal's packing fraction and coordination number equal the analytic values,
and results.h5, pipeline.json and the frames carry their provenance (pipeline, version, commit,
seed), the pipeline naming the folder the run wrote (the --out given, not the file's
output.dir)."""
import json
import math
import sys

import h5py

out = sys.argv[1]
expected = {  # lattice: (phi, z)
    "square": (math.pi / 4, 4),
    "triangular": (math.pi / (2 * math.sqrt(3)), 6),
    "sc": (math.pi / 6, 6),
    "bcc": (math.pi * math.sqrt(3) / 8, 8),
    "fcc": (math.pi / (3 * math.sqrt(2)), 12),
    "hcp": (math.pi / (3 * math.sqrt(2)), 12),
}
failures = []


def check_output_dir(pipeline, where):
    if pipeline["output"]["dir"] != out:
        failures.append(f"{where}: output.dir {pipeline['output']['dir']!r}, the run wrote {out!r}")


with open(f"{out}/pipeline.json") as f:
    check_output_dir(json.load(f), "pipeline.json")
with h5py.File(f"{out}/results.h5", "r") as f:
    pipeline = json.loads(f.attrs["pipeline"])
    check_output_dir(pipeline, "results.h5")
    for key in ("granpipe_version", "git_commit", "seed"):
        if key not in f.attrs:
            failures.append(f"results.h5 lacks the {key} attribute")
    if int(f.attrs["seed"]) != pipeline["seed"]:
        failures.append("results.h5 seed differs from the pipeline's")
    lattices = pipeline["sweep"]["parameters"]["source.params.lattice"]
    for k, lattice in enumerate(lattices):
        group = f[f"point_{k:03d}/packing"]
        phi, z = float(group["phi"][()]), float(group["z_mean"][()])
        phi_exact, z_exact = expected[lattice]
        if abs(phi - phi_exact) > 1e-12 * phi_exact:
            failures.append(f"{lattice}: phi {phi!r}, expected {phi_exact!r}")
        if z != z_exact:
            failures.append(f"{lattice}: z {z}, expected {z_exact}")
        with h5py.File(f"{out}/point_{k:03d}/frames.h5", "r") as frames:
            provenance = json.loads(frames["granpipe"].attrs["provenance"])
            check_output_dir(provenance["pipeline"], f"point_{k:03d}/frames.h5")
            if (provenance["sweep_point"], provenance["sweep_seeds"]) != (k, "per_point"):
                failures.append(f"point_{k:03d}/frames.h5 provenance: point "
                                f"{provenance['sweep_point']}, seeds {provenance['sweep_seeds']}")
            if provenance["pipeline"]["source"]["params"]["lattice"] != lattice:
                failures.append(f"point_{k:03d}/frames.h5 provenance names the wrong lattice")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"{len(lattices)} crystals: phi and z exact; provenance present")
