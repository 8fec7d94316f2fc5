"""Checks Table II of the Brazil-nut paper (003_35e4a4def860c0d4.txt) on the compression-peak
frame of bnp_mst.json (data-samples/bnp_t10.h5), from a run of reprocess_mst.json read with
h5py: pass 1 recovers the force networks' particle sets (the largest TCP has the largest
network's N_P and is a tree, N_E = N_P - 1; as many other TCPs as other networks, with the
same edges), two passes recover over 90 % of the contacts and four over 99 %, and the force
networks of force_network agree with the contact network mst counts."""
import sys

import h5py

out = sys.argv[1]
failures = []

with h5py.File(f"{out}/results.h5", "r") as f:
    table_ii = f["mst"]["table_ii"]
    rows = {int(p): k for k, p in enumerate(table_ii["pass"][()])}
    get = lambda name, p: float(table_ii[name][rows[p]])
    n_p = get("network_largest_particles", 1)
    if get("tcp_largest_particles", 1) != n_p:
        failures.append(f"pass 1: largest TCP has {get('tcp_largest_particles', 1)} particles, "
                        f"the largest force network {n_p}")
    if get("tcp_largest_edges", 1) != n_p - 1:
        failures.append(f"pass 1: largest TCP has {get('tcp_largest_edges', 1)} edges, not N_P - 1")
    for a, b in (("tcp_others", "network_others"), ("tcp_other_edges", "network_other_edges")):
        if get(a, 1) != get(b, 1):
            failures.append(f"pass 1: {a} = {get(a, 1)}, {b} = {get(b, 1)}")
    if not get("recovered_fraction", 2) > 0.90:
        failures.append(f"two passes recover {get('recovered_fraction', 2):.4f} of the contacts")
    if not get("recovered_fraction", 4) > 0.99:
        failures.append(f"four passes recover {get('recovered_fraction', 4):.4f} of the contacts")
    fn = f["force_network"]["per_frame"]
    if float(fn["largest_particles"][0]) != n_p or float(fn["networks"][0]) != get("network_others", 1) + 1:
        failures.append("force_network's networks differ from mst's contact network")
    if n_p < 1000:
        failures.append(f"the largest network has only {n_p} particles: not a compression-peak frame")

for line in failures:
    print(line)
sys.exit(1 if failures else 0)
