#!/usr/bin/python3
"""The Brazil-nut scene in granpipe, LAMMPS and LIGGGHTS, back to back (issue 12).

usage: bnp_side_by_side.py [--build DIR] [--ref-dir DIR] [--rounds N] [--keep DIR]

All three start from the same settled packing (granpipe: data-samples/bnp_settled.h5, the
import of the reference settled.data; the others: settled.data(.gz) in --ref-dir), with the
same contact law, parameters, time step, skin and wall motion, and run 5000 warm-up steps
then 25000 timed ones, on 1 and then 2 threads or MPI processes. The runs interleave
(granpipe, LAMMPS, LIGGGHTS on 1, then the same on 2, per round) so that the load of a
shared machine hits all alike; a run that got under 90 % of its cores is flagged. An engine
that is not installed is skipped, and the report says so: granpipe never needs them.

Prints a Markdown report: the instruction set granpipe's force loops ran with (AVX-512, AVX2
or baseline, from run.log: the speeds depend on it), particle-steps per second (and per
core), the ratios, the speed-up from 1 to 2, the physics check (kinetic energy and highest
particle, granpipe against the engines) and where the time goes in granpipe and in LAMMPS.
"""
import argparse
import gzip
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
N_PARTICLES = 7601
DT = 2e-4
KN, GAMMA_N, MU = 2.0e5, 42.398, 0.5
KT, GAMMA_T = 2.0 / 7.0 * KN, GAMMA_N / 2
AMPLITUDE, FREQUENCY = 7.5, 0.107
SKIN = 0.2
DENSITIES = (1.91, 13.54)  # small, large (the LAMMPS types 1 and 2)
CYLINDER_RADIUS = 6.125
LOW_CPU_SHARE = 0.90
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1", "OMP_NUM_THREADS": "1"}
ENGINES = ("granpipe", "LAMMPS", "LIGGGHTS")


# ---------------------------------------------------------------- inputs


def granpipe_pipeline(steps, every):
    return {
        "name": "bnp_side_by_side",
        "description": "The settled Brazil-nut bed shaken from rest (tests/bench/bnp_side_by_side.py)",
        "seed": 1,
        "source": {"plugin": "dem",
                   "params": {"initial_file": os.path.join(REPO, "data-samples", "bnp_settled.h5"),
                              "species": [{"name": "small", "density": DENSITIES[0]},
                                          {"name": "large", "density": DENSITIES[1]}],
                              "contacts": {"*": {"k_n": KN, "k_t": KT, "gamma_n": GAMMA_N,
                                                 "gamma_t": GAMMA_T, "mu": MU}},
                              "walls": {"k_n": KN, "k_t": KT, "gamma_n": GAMMA_N, "gamma_t": GAMMA_T, "mu": MU},
                              "drive": {"form": "one_minus_cos", "amplitude": AMPLITUDE, "frequency": FREQUENCY},
                              "law": "linear", "friction": True, "rotation": True, "skin": SKIN,
                              "dt": DT, "duration": steps * DT, "save_every": every}},
        "analyzers": [],
        "output": {"dir": "out", "frame_stride": 1},
    }


# The LAMMPS input: GRANULAR package, analytic walls moving with `wiggle`, the form
# z = A (1 - cos wt) of granpipe's one_minus_cos drive. Split along z on 2 processes.
LAMMPS_INPUT = f"""units lj
atom_style sphere
atom_modify map array
boundary f f m
newton off
comm_modify vel yes
if "${{decomp}} == z" then "processors 1 1 *" else "processors * 1 1"
read_data settled.data
neighbor {SKIN} bin
neigh_modify delay 0 every 1 check yes
pair_style gran/hooke/history {KN} {KT} {GAMMA_N} {GAMMA_T} {MU} 1
pair_coeff * *
timestep {DT}
fix integ all nve/sphere
fix grav all gravity 1.0 vector 0 0 -1
fix wcyl all wall/gran hooke/history {KN} {KT} {GAMMA_N} {GAMMA_T} {MU} 1 zcylinder {CYLINDER_RADIUS} wiggle z {AMPLITUDE} {1 / FREQUENCY}
fix wbase all wall/gran hooke/history {KN} {KT} {GAMMA_N} {GAMMA_T} {MU} 1 zplane 0.0 NULL wiggle z {AMPLITUDE} {1 / FREQUENCY}
if "${{decomp}} == z" then "balance 1.0 shift z 20 1.02" "fix bal all balance 5000 1.05 shift z 20 1.02"
compute rke all erotate/sphere
compute zmax all reduce max z
thermo_style custom step time atoms ke c_rke c_zmax
thermo_modify norm no lost error
thermo ${{nw}}
run ${{nw}}
run ${{nt}}
"""

# The LIGGGHTS input: its primitive walls cannot move, so the container is two triangle
# meshes moved with the velocity A w sin(wt), which integrates to the same A (1 - cos wt).
# ('units si' only because LIGGGHTS wants it; the numbers are the nondimensional ones.)
LIGGGHTS_INPUT = f"""atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
processors * 1 1
read_data settled_lig.data
neighbor {SKIN} bin
neigh_modify delay 0
fix m1 all property/global kn peratomtypepair 2 {KN} {KN} {KN} {KN}
fix m2 all property/global kt peratomtypepair 2 {KT} {KT} {KT} {KT}
fix m3 all property/global gamman peratomtypepair 2 {GAMMA_N} {GAMMA_N} {GAMMA_N} {GAMMA_N}
fix m4 all property/global gammat peratomtypepair 2 {GAMMA_T} {GAMMA_T} {GAMMA_T} {GAMMA_T}
fix m5 all property/global coefficientFriction peratomtypepair 2 {MU} {MU} {MU} {MU}
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
timestep {DT}
fix grav all gravity 1.0 vector 0.0 0.0 -1.0
fix cyl all mesh/surface file cyl.stl type 1
fix base all mesh/surface file base.stl type 1
fix walls all wall/gran model hooke/stiffness tangential history mesh n_meshes 2 meshes cyl base
variable zero equal 0.0
variable w equal {2 * math.pi * FREQUENCY}
variable vz equal {AMPLITUDE}*v_w*sin(v_w*step*{DT})
fix mvc all move/mesh mesh cyl linear/variable v_zero v_zero v_vz
fix mvb all move/mesh mesh base linear/variable v_zero v_zero v_vz
fix integr all nve/sphere
compute rke all erotate/sphere
compute zmax all reduce max z
thermo_style custom step atoms ke c_rke c_zmax
thermo_modify norm no lost error
thermo ${{nw}}
run ${{nw}}
run ${{nt}}
"""


def read_settled(ref_dir):
    """The text of settled.data (or of settled.data.gz) in the reference folder."""
    for name, opener in (("settled.data", open), ("settled.data.gz", gzip.open)):
        path = os.path.join(ref_dir, name)
        if os.path.exists(path):
            with opener(path, "rt") as f:
                return f.read()
    raise SystemExit(f"{ref_dir}: expected settled.data or settled.data.gz (the reference packing), found neither")


def liggghts_data(settled):
    """settled.data in a box tall enough for the moving meshes, as LIGGGHTS reads it."""
    sections, current = {"Atoms": [], "Velocities": []}, None
    for line in settled.splitlines():
        text = line.split("#")[0].strip()
        if not text:
            continue
        if text[0].isalpha():
            current = text if text in sections else None
        elif current:
            sections[current].append(text.split()[:7])
    out = [f"BNP settled packing\n\n{len(sections['Atoms'])} atoms\n2 atom types\n",
           "-6.5 6.5 xlo xhi\n-6.5 6.5 ylo yhi\n-1.0 216.5 zlo zhi\n"]
    for name, rows in sections.items():
        if rows:
            rows.sort(key=lambda w: int(w[0]))
            out.append(f"{name}\n\n" + "\n".join(" ".join(w) for w in rows) + "\n")
    return "\n".join(out)


def stl(name, triangles):
    lines = [f"solid {name}"]
    for a, b, c in triangles:
        u, v = np.subtract(b, a), np.subtract(c, a)
        n = np.cross(u, v)
        n /= np.linalg.norm(n)
        lines += [f"facet normal {n[0]:g} {n[1]:g} {n[2]:g}", " outer loop"]
        lines += [f"  vertex {p[0]:.6f} {p[1]:.6f} {p[2]:.6f}" for p in (a, b, c)]
        lines += [" endloop", "endfacet"]
    return "\n".join(lines + [f"endsolid {name}", ""])


def cylinder_mesh(around=96, height=200.0, rows=10):
    """The side wall, 96 facets around and rows 20 tall (finer rows were twice as slow)."""
    ring = [(CYLINDER_RADIUS * math.cos(2 * math.pi * k / around),
             CYLINDER_RADIUS * math.sin(2 * math.pi * k / around)) for k in range(around + 1)]
    tris = []
    for r in range(rows):
        z0, z1 = r * height / rows, (r + 1) * height / rows
        for k in range(around):
            p00, p10 = (*ring[k], z0), (*ring[k + 1], z0)
            p01, p11 = (*ring[k], z1), (*ring[k + 1], z1)
            tris += [(p00, p11, p10), (p00, p01, p11)]
    return tris


def base_mesh(fan=48):
    """A disk a little wider than the cylinder, so that the two meet."""
    r = CYLINDER_RADIUS + 0.2
    rim = [(r * math.cos(2 * math.pi * k / fan), r * math.sin(2 * math.pi * k / fan), 0.0) for k in range(fan + 1)]
    return [((0.0, 0.0, 0.0), rim[k], rim[k + 1]) for k in range(fan)]


def write_inputs(work, ref_dir, engines, steps, every):
    settled = read_settled(ref_dir) if {"LAMMPS", "LIGGGHTS"} & set(engines) else None
    files = {"granpipe.json": json.dumps(granpipe_pipeline(steps, every), indent=1)}
    if "LAMMPS" in engines:
        files.update({"in.lammps": LAMMPS_INPUT, "settled.data": settled})
    if "LIGGGHTS" in engines:
        files.update({"in.liggghts": LIGGGHTS_INPUT, "settled_lig.data": liggghts_data(settled),
                      "cyl.stl": stl("cyl", cylinder_mesh()), "base.stl": stl("base", base_mesh())})
    for name, text in files.items():
        with open(os.path.join(work, name), "w") as f:
            f.write(text)


# ---------------------------------------------------------------- runs


def run_timed(cmd, cwd, env, cores):
    """Runs cmd; returns wall seconds and the share of `cores` its process tree used."""
    load = os.getloadavg()[0]
    with open(os.path.join(cwd, "stdout.txt"), "w") as out, open(os.path.join(cwd, "stderr.txt"), "w") as err:
        start = time.perf_counter()
        child = subprocess.Popen(cmd, cwd=cwd, env=dict(os.environ, **env), stdout=out, stderr=err)
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        with open(os.path.join(cwd, "stderr.txt")) as f:
            tail = f.read()[-600:]
        raise SystemExit(f"{' '.join(cmd)} (in {cwd}) failed with exit code {child.returncode}:\n{tail}")
    return {"wall": wall, "cpu_share": (usage.ru_utime + usage.ru_stime) / (wall * cores), "load_before": load,
            "maxrss_kb": usage.ru_maxrss}


def run_dir(work, name):
    path = os.path.join(work, name)
    os.makedirs(path)
    for f in os.listdir(work):
        if os.path.isfile(os.path.join(work, f)):
            os.symlink(os.path.join(work, f), os.path.join(path, f))
    return path


def run_granpipe(work, build, cores, label, steps):
    cwd = run_dir(work, label)
    env = {"GRANPIPE_PLUGIN_PATH": os.path.join(build, "lib", "granpipe", "plugins"), "OMP_NUM_THREADS": str(cores)}
    cmd = [os.path.join(build, "bin", "granpipe"), "granpipe.json", "--threads", str(cores), "--quiet", "--no-report", "--out", "out",
           "--set", f"source.params.duration={steps * DT!r}"]
    record = run_timed(cmd, cwd, env, cores)
    record["kernels"] = granpipe_kernels(os.path.join(cwd, "out", "run.log"))
    record["frames"] = granpipe_frames(os.path.join(cwd, "out", "frames.h5"))
    record["profile"] = granpipe_profile(os.path.join(cwd, "out", "results.h5"))
    return record


def granpipe_kernels(run_log):
    """The instruction set the dem force loops ran with, from run.log ("AVX-512", "AVX2",
    "baseline"): the speeds depend on it."""
    with open(run_log) as f:
        for line in f:
            found = re.match(r"dem: force loops (?:compiled )?for ([^,]+),", line)
            if found:
                return found.group(1)
    return "unknown (this build's dem source does not say)"


def run_engine(work, engine, cores, label, args):
    cwd = run_dir(work, label)
    exe, script = {"LAMMPS": ("lmp", "in.lammps"), "LIGGGHTS": ("liggghts", "in.liggghts")}[engine]
    cmd = [shutil.which(exe), "-in", script, "-log", "log.txt",
           "-var", "nw", str(args.warmup), "-var", "nt", str(args.timed), "-var", "decomp", "z"]
    if cores > 1:
        cmd = ["mpirun", "-np", str(cores)] + cmd
    record = run_timed(cmd, cwd, MPI_ENV, cores)
    record.update(parse_log(os.path.join(cwd, "log.txt")))
    return record


# ---------------------------------------------------------------- reading results


THERMO_NAMES = {"KinEng": "ke", "c_rke": "rke", "rke": "rke", "c_zmax": "zmax", "zmax": "zmax", "Step": "step"}
# "Pair    | min | avg | max | %varavg | %total" (LAMMPS) or "Pair  time (%) = 1.2 (50.1)" (LIGGGHTS)
BREAKDOWN_LINE = re.compile(r"^(\w+)\s+(?:\|[^|]*\|[^|]*\|[^|]*\|[^|]*\|\s*(\S+)|time \(%\) = \S+ \((\S+)\))$")


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def parse_log(path):
    """Thermo rows, and the timed run's loop time, neighbour builds and timing breakdown."""
    with open(path) as f:
        lines = f.read().splitlines()
    thermo, header, loops, breakdowns, builds = {}, None, [], [], []
    for line in lines:
        words, section = line.split(), BREAKDOWN_LINE.match(line.strip())
        if words[:1] == ["Step"]:
            header = [THERMO_NAMES.get(w, w) for w in words]
        elif header and words[:2] == ["Loop", "time"]:
            header = None
            loops.append(float(words[3]))
            breakdowns.append({})
        elif header and len(words) == len(header) and all(map(is_number, words)):
            row = dict(zip(header, map(float, words)))
            thermo[int(row["step"])] = row
        elif section and breakdowns and section.group(1) != "Section":
            breakdowns[-1][section.group(1)] = float(section.group(2) or section.group(3))
        elif line.startswith("Neighbor list builds"):
            builds.append(int(line.split("=")[1]))
    if len(loops) < 2:
        raise SystemExit(f"{path}: expected two 'Loop time' lines (warm-up and timed run), found {len(loops)}")
    return {"timed": loops[-1], "thermo": thermo, "breakdown": breakdowns[-1],
            "rebuilds": builds[-1] if builds else None}


def granpipe_frames(path):
    """Per frame step: translational and rotational kinetic energy and the highest centre."""
    with h5py.File(path, "r") as f:
        p = f["particles/all"]
        steps = p["velocity/step"][:]
        radius, species = p["radius/value"][0], p["species/value"][0]
        mass = np.asarray(DENSITIES)[species] * 4.0 / 3.0 * math.pi * radius ** 3
        rows = {}
        for k, step in enumerate(steps):
            v, w = p["velocity/value"][k], p["angular_velocity/value"][k]
            rows[int(step)] = {"ke": 0.5 * np.dot(mass, np.sum(v * v, axis=1)),
                               "rke": 0.5 * np.dot(0.4 * mass * radius ** 2, np.sum(w * w, axis=1)),
                               "zmax": float(np.max(p["position/value"][k][:, 2]))}
    return rows


def granpipe_profile(path):
    """The dem source's per-interval timing table, summed over the rows after the first."""
    with h5py.File(path, "r") as f:
        for name, group in f.get("source", {}).items():
            if isinstance(group, h5py.Group) and "force_seconds" in group:
                summed = ("steps", "seconds", "force_seconds", "integrate_seconds", "neighbour_seconds", "rebuilds")
                return {c: float(np.sum(group[c][1:])) for c in summed if c in group}
    return None


def add_granpipe_timing(records, warmup_walls):
    """Timed seconds: the table's rows after the warm-up, or else whole run minus warm-up run."""
    for r in records:
        if r["profile"]:
            r["timed"] = r["profile"]["seconds"]
            r["rebuilds"] = int(r["profile"].get("rebuilds", 0))
        else:
            r["timed"] = r["wall"] - warmup_walls[r["cores"]]
            r["rebuilds"] = None


# ---------------------------------------------------------------- report


def rate(r, timed_steps):
    return N_PARTICLES * timed_steps / r["timed"]


def best(records, engine, cores):
    runs = [r for r in records if r["engine"] == engine and r["cores"] == cores]
    return min(runs, key=lambda r: r["timed"]) if runs else None


def report_speed(records, args):
    print("| engine | threads / processes | timed s | ms per step | particle-steps/s | per core | CPU share "
          "| per CPU-second | load before |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in records:
        flag = " **(low)**" if r["cpu_share"] < LOW_CPU_SHARE else ""
        per_core = rate(r, args.timed) / r["cores"]
        print(f"| {r['engine']} | {r['cores']} | {r['timed']:.2f} | {r['timed'] / args.timed * 1e3:.3f} | "
              f"{rate(r, args.timed):.3g} | {per_core:.3g} | {r['cpu_share'] * 100:.0f} %{flag} | "
              f"{per_core / r['cpu_share']:.3g} | {r['load_before']:.2f} |")
    print("\n(CPU share: user + system time of the whole run over wall time and cores. 'Per CPU-second' divides "
          "by it: what a core did while it ran the engine; an estimate for 1 core under load, not for 2, where "
          "a waiting thread or process spins and a preempted one stalls the other.)\n")
    for cores in args.cores:
        gp = best(records, "granpipe", cores)
        for other in ENGINES[1:]:
            o = best(records, other, cores)
            if gp and o:
                print(f"- granpipe / {other} on {cores}: {o['timed'] / gp['timed']:.2f}")
    if len(args.cores) == 2:
        for engine in ENGINES:
            one, two = best(records, engine, args.cores[0]), best(records, engine, args.cores[1])
            if one and two:
                print(f"- {engine} speed-up {args.cores[0]} -> {args.cores[1]}: {one['timed'] / two['timed']:.2f}")
    if len({r["round"] for r in records}) > 1:
        print("- (ratios and speed-ups from the fastest run of each case)")
    low = [f"{r['engine']} {r['cores']} (round {r['round']})" for r in records if r["cpu_share"] < LOW_CPU_SHARE]
    print(f"- runs under {LOW_CPU_SHARE:.0%} CPU share: {', '.join(low) if low else 'none'}")
    print()


def report_physics(records, args):
    gp = best(records, "granpipe", args.cores[0])
    others = [e for e in ENGINES[1:] if best(records, e, args.cores[0])]
    if not gp or not others:
        return
    print("Physics over the timed window (granpipe and engines on 1; KE translational, rotational; zmax the highest centre):\n")
    head = "| step | time | KE granpipe |" + "".join(f" KE {e} | diff |" for e in others)
    head += " rot. KE granpipe |" + "".join(f" rot. KE {e} |" for e in others)
    head += " zmax granpipe |" + "".join(f" zmax {e} | diff |" for e in others)
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for step in sorted(gp["frames"]):
        if step < args.warmup:
            continue
        g = gp["frames"][step]
        cells = [str(step), f"{step * DT:g}", f"{g['ke']:.4g}"]
        for e in others:
            row = best(records, e, args.cores[0])["thermo"].get(step)
            cells += [f"{row['ke']:.4g}", f"{g['ke'] / row['ke'] - 1:+.1%}"] if row else ["", ""]
        cells.append(f"{g['rke']:.4g}")
        for e in others:
            row = best(records, e, args.cores[0])["thermo"].get(step)
            cells.append(f"{row['rke']:.4g}" if row else "")
        cells.append(f"{g['zmax']:.3f}")
        for e in others:
            row = best(records, e, args.cores[0])["thermo"].get(step)
            cells += [f"{row['zmax']:.3f}", f"{g['zmax'] - row['zmax']:+.3f}"] if row else ["", ""]
        print("| " + " | ".join(cells) + " |")
    print()
    for e in others:
        print(agreement(gp["frames"], best(records, e, args.cores[0])["thermo"], args.warmup, f"granpipe vs {e}"))
    if len(others) == 2:
        lmp, lig = (best(records, e, args.cores[0])["thermo"] for e in others)
        print(agreement(lig, lmp, args.warmup, "LIGGGHTS vs LAMMPS (the spread between the two engines)"))
    for c in args.cores[1:]:
        g = best(records, "granpipe", c)
        if g:
            print(agreement(gp["frames"], g["frames"], args.warmup, f"granpipe {args.cores[0]} vs {c} threads"))
    print()


def agreement(mine, theirs, first_step, what):
    """The largest relative differences over the common steps from first_step on."""
    steps = [s for s in mine if s >= first_step and s in theirs]
    if not steps:
        return f"- {what}: no common steps"
    worst = {k: max(abs(mine[s][k] / theirs[s][k] - 1) for s in steps) for k in ("ke", "rke", "zmax")}
    return (f"- {what}, largest difference over steps {steps[0]}-{steps[-1]}: translational KE {worst['ke']:.1%}, "
            f"rotational KE {worst['rke']:.1%}, highest particle {worst['zmax']:.2%}")


def report_profile(records, args):
    print("Where the time goes (timed window; granpipe's dem timing table, the engines' own breakdowns):\n")
    for cores in args.cores:
        gp = best(records, "granpipe", cores)
        if gp and gp["profile"]:
            p = gp["profile"]
            parts = {"forces (pairs + walls)": p["force_seconds"], "integration": p["integrate_seconds"],
                     "neighbour lists": p["neighbour_seconds"]}
            parts["other"] = p["seconds"] - sum(parts.values())
            text = ", ".join(f"{k} {v / p['seconds']:.0%}" for k, v in parts.items())
            print(f"- granpipe on {cores}: {text}; {gp['rebuilds']} rebuilds")
        elif gp:
            print(f"- granpipe on {cores}: no timing table in results.h5 (this build's dem source writes none)")
        for engine in ENGINES[1:]:
            r = best(records, engine, cores)
            if r and r["breakdown"]:
                text = ", ".join(f"{k} {v:.0f} %" for k, v in r["breakdown"].items())
                print(f"- {engine} on {cores}: {text}; {r['rebuilds']} rebuilds")
    print()


# ---------------------------------------------------------------- main


def available(engines):
    kept = []
    for engine in engines:
        exe = {"granpipe": None, "LAMMPS": "lmp", "LIGGGHTS": "liggghts"}[engine]
        if exe and not shutil.which(exe):
            print(f"{engine}: skipped, `{exe}` is not installed")
        elif exe and not shutil.which("mpirun"):
            print(f"{engine}: skipped, `mpirun` (openmpi) is not installed")
        else:
            kept.append(engine)
    return kept


def run_all(work, args, engines):
    records, warmup_walls = [], {}
    for rnd in range(1, args.rounds + 1):
        for cores in args.cores:
            for engine in engines:
                label = f"{engine}_{cores}_{rnd}"
                print(f"running {label} ...", file=sys.stderr, flush=True)
                if engine == "granpipe":
                    r = run_granpipe(work, args.build, cores, label, args.warmup + args.timed)
                    if not r["profile"] and cores not in warmup_walls:
                        warmup_walls[cores] = run_granpipe(work, args.build, cores, label + "_warmup", args.warmup)["wall"]
                else:
                    r = run_engine(work, engine, cores, label, args)
                r.update(engine=engine, cores=cores, round=rnd)
                records.append(r)
    add_granpipe_timing([r for r in records if r["engine"] == "granpipe"], warmup_walls)
    return records


def machine():
    model = next((l.split(":", 1)[1].strip() for l in subprocess.run(["lscpu"], capture_output=True, text=True)
                  .stdout.splitlines() if l.startswith("Model name")), "unknown")
    return f"{model}, {os.cpu_count()} cores"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(REPO, "build"), help="granpipe build directory")
    parser.add_argument("--ref-dir", default=os.path.join(REPO, "..", "shared", "bench", "bnp"),
                        help="folder with settled.data(.gz) (default: ../shared/bench/bnp, relative to the project root)")
    parser.add_argument("--rounds", type=int, default=1, help="repeat the interleaved runs")
    parser.add_argument("--warmup", type=int, default=5000, help="warm-up steps, also the frame and thermo interval")
    parser.add_argument("--timed", type=int, default=25000, help="timed steps (small values: a quick check of the script)")
    parser.add_argument("--cores", type=int, nargs="+", default=[1, 2], help="threads / processes")
    parser.add_argument("--keep", help="run in this new folder and keep it (logs, frames) instead of a temporary one")
    args = parser.parse_args()
    if args.warmup < 1 or args.timed % args.warmup:
        raise SystemExit(f"--timed: expected a multiple of --warmup (the frame and thermo interval), got {args.timed}")
    engines = available(ENGINES)
    start, load = time.strftime("%Y-%m-%d %H:%M"), os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as tmp:
        work = args.keep or tmp
        if args.keep:
            os.makedirs(work)
        write_inputs(work, args.ref_dir, engines, args.warmup + args.timed, args.warmup)
        records = run_all(work, args, engines)
    kernels = sorted({r["kernels"] for r in records if r["engine"] == "granpipe"})
    print(f"\n{start}, {machine()}, load average {load:.2f} at the start, {os.getloadavg()[0]:.2f} at the end; "
          f"N = {N_PARTICLES}, {args.warmup} warm-up + {args.timed} timed steps; "
          f"granpipe's force loops: {', '.join(kernels) or 'not run'}\n")
    report_speed(records, args)
    report_physics(records, args)
    report_profile(records, args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
