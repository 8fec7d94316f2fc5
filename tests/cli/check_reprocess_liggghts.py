"""Checks a run of pipelines/reprocess_liggghts.json (with save_frames) against the LIGGGHTS
dumps it read, parsed here from their raw text without granpipe: per snapshot, the contact
table holds every pair entry (compute pair/gran/local) then every wall entry (compute
wall/gran/local), with the atom ids of each pair, and the sum of |force_normal| over each
equals what LIGGGHTS wrote to 1e-12; force_network's edges and total force (mean_force x
samples) are the pair entries with a non-zero normal force and the sum of their |F_n|;
intruder's base contacts are the wall entries.
Usage: check_reprocess_liggghts.py OUT_DIR DATA_SAMPLES"""
import gzip
import math
import sys

import h5py
import numpy as np

out, samples = sys.argv[1], sys.argv[2]


def snapshots(path):
    """{timestep: rows of floats} of a dump local, from its text."""
    result, lines = {}, gzip.open(path, "rt").read().splitlines()
    k = 0
    while k < len(lines):
        assert lines[k] == "ITEM: TIMESTEP", (path, k, lines[k])
        step, count = int(lines[k + 1]), int(lines[k + 3])
        assert lines[k + 2] == "ITEM: NUMBER OF ENTRIES" and lines[k + 8].startswith("ITEM: ENTRIES")
        result[step] = [[float(w) for w in line.split()] for line in lines[k + 9:k + 9 + count]]
        k += 9 + count
    return result


def atom_ids(path):
    """{timestep: ids in file order} of a dump custom with id first."""
    result, lines = {}, gzip.open(path, "rt").read().splitlines()
    k = 0
    while k < len(lines):
        step, count = int(lines[k + 1]), int(lines[k + 3])
        result[step] = [int(line.split()[0]) for line in lines[k + 9:k + 9 + count]]
        k += 9 + count
    return result


# pos id force force_normal contactArea delta: ids in columns 7, 8 (a wall's atom in 9),
# force_normal in 13-15 (1-based).
pairs = snapshots(f"{samples}/liggghts_bed_pairs.dump.gz")
walls = snapshots(f"{samples}/liggghts_bed_walls.dump.gz")
ids = atom_ids(f"{samples}/liggghts_bed.dump.gz")
norm = lambda row: math.sqrt(row[12] ** 2 + row[13] ** 2 + row[14] ** 2)

failures = []
close = lambda a, b: abs(a - b) <= 1e-12 * abs(b)
with h5py.File(f"{out}/frames.h5", "r") as f, h5py.File(f"{out}/results.h5", "r") as r:
    steps = list(f["particles/all/position/step"][()])
    c = f["granpipe/contacts"]
    per_frame = r["force_network/per_frame"]
    base = r["intruder/per_frame"]["base_contacts"][()]
    if steps != sorted(pairs):
        failures.append(f"frames of steps {steps}, the pair dump has {sorted(pairs)}")
    for t, step in enumerate(steps):
        rows = slice(c["offset"][t], c["offset"][t] + c["count"][t])
        i, j, f_n = c["i"][rows], c["j"][rows], c["normal_force"][rows]
        p, w = pairs[step], walls[step]
        id_of = np.array(sorted(ids[step]))
        if len(i) != len(p) + len(w):
            failures.append(f"step {step}: {len(i)} contacts, LIGGGHTS wrote {len(p)} + {len(w)}")
            continue
        got_pairs = [(id_of[a], id_of[b]) for a, b in zip(i[:len(p)], j[:len(p)])]
        if got_pairs != [(int(e[6]), int(e[7])) for e in p]:
            failures.append(f"step {step}: pair ids differ from the dump's")
        if list(j[len(p):]) != [-6] * len(w) or [id_of[a] for a in i[len(p):]] != [int(e[8]) for e in w]:
            failures.append(f"step {step}: wall contacts are not the dump's atoms on the base (-6)")
        pair_total, wall_total = sum(map(norm, p)), sum(map(norm, w))
        table = np.sqrt((f_n ** 2).sum(axis=1))
        for name, got, want in (("pair", table[:len(p)].sum(), pair_total),
                                ("wall", table[len(p):].sum(), wall_total)):
            if not close(got, want):
                failures.append(f"step {step}: total {name} normal force {got!r}, LIGGGHTS wrote {want!r}")
        loaded = [norm(e) for e in p if norm(e) > 0]
        edges, samples_, mean = (per_frame[k][t] for k in ("network_contacts", "samples", "mean_force"))
        if edges != len(loaded) or samples_ != len(loaded):
            failures.append(f"step {step}: force_network counted {edges} edges, LIGGGHTS wrote {len(loaded)} loaded pairs")
        elif not close(mean * samples_, sum(loaded)):
            failures.append(f"step {step}: force_network's total force {mean * samples_!r}, LIGGGHTS wrote {sum(loaded)!r}")
        if base[t] != len(w):
            failures.append(f"step {step}: intruder counted {base[t]} base contacts, LIGGGHTS wrote {len(w)}")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"{len(steps)} snapshots: contact counts, ids and total normal forces are LIGGGHTS's")
