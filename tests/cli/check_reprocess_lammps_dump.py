"""Checks a run of pipelines/reprocess_lammps_dump.json through an independent reader (h5py):
the four snapshots of the dump were read, in order, with their steps and times (dt = 1),
and the packing fraction of each is the jittered crystal's, pi / (3 sqrt 2) x 0.95^3, to
1e-12 (in a periodic box it depends only on the radii and the box, which the dump keeps
to 16 digits), without contacts."""
import math
import sys

import h5py

out = sys.argv[1]
phi_exact = math.pi / (3 * math.sqrt(2)) * 0.95**3
failures = []
with h5py.File(f"{out}/results.h5", "r") as f:
    frames = f["packing/per_frame"]
    steps, times = list(frames["step"][()]), list(frames["time"][()])
    if steps != [0, 1, 2, 3] or times != [0.0, 1.0, 2.0, 3.0]:
        failures.append(f"steps {steps} and times {times}, expected 0 to 3")
    for step, phi in zip(steps, frames["phi"][()]):
        if abs(phi - phi_exact) > 1e-12 * phi_exact:
            failures.append(f"step {step}: phi {phi!r}, expected {phi_exact!r}")
    if list(frames["z_mean"][()]) != [0.0] * 4:
        failures.append(f"z_mean {list(frames['z_mean'][()])}, expected no contacts")
    if float(f["source/frames_read"][()]) != 4:
        failures.append(f"frames_read {f['source/frames_read'][()]}, expected 4")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"4 snapshots: steps, times and phi = {phi_exact:.12f} exact")
