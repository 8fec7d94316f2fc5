"""scripts/pool_ageing.py on hand-made realizations: A is the mean of the realizations'
squared differences and A_err the standard error across them; Eq. (6) fitted to pooled rows
that follow it recovers A_inf, B and tau within three errors, and rows growing in proportion
to t are reported not determined (status 3, NaN); realizations run one per run pool as one
sweep, one met twice is refused; a missing table is refused in one line with exit code 2."""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

script = sys.argv[1]
truth = (0.05, 1.0, 20.0)


def eq6(t):
    a_inf, b, tau = truth
    return a_inf * (1.0 - 1.0 / (1.0 + b * math.log1p(t / tau)))


def write(out, name, lines):
    with open(os.path.join(out, name), "w") as f:
        f.write("# granpipe test\n" + "\n".join(lines) + "\n")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


failures = []
with tempfile.TemporaryDirectory() as out:
    with open(os.path.join(out, "pipeline.json"), "w") as f:
        json.dump({"sweep": {"parameters": {"source.params.replica": [0, 1]}}}, f)
    write(out, "sweep.points.csv", ["point,source.params.replica", "0,0", "1,1"])
    taps = range(1, 200)
    # The two realizations straddle the law by +-1e-4, alternating: their mean is the law.
    for point, sign in ((0, 1.0), (1, -1.0)):
        lines = ["t_w,t,squared_difference", "3,1,0.5"]
        lines += [f"10,{t},{eq6(t) + sign * (1e-4 if t % 2 else -1e-4)!r}" for t in taps]
        # Growing in proportion to t, no sign of levelling off: Eq. (6) is not determined.
        lines += [f"20,{t},{1e-4 * t + sign * (1e-5 if t % 2 else -1e-5)!r}" for t in taps]
        write(out, f"point_00{point}.compaction.ageing.csv", lines)
    r = subprocess.run([sys.executable, script, out], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        pooled = rows(os.path.join(out, "pooled.compaction.ageing.csv"))
        first = pooled[0]
        if (float(first["t_w"]), float(first["A"]), float(first["A_err"])) != (3.0, 0.5, 0.0):
            failures.append(f"pooled row {first}")
        second = pooled[1]
        if abs(float(second["A"]) - eq6(1.0)) > 1e-12 or abs(float(second["A_err"]) - 1e-4) > 1e-12:
            failures.append(f"pooled row {second}: expected A {eq6(1.0)}, A_err 1e-4")
        fits = {float(f["t_w"]): f for f in rows(os.path.join(out, "pooled.compaction.ageing_fits.csv"))}
        if not math.isnan(float(fits[3.0]["A_inf"])) or fits[3.0]["status"] != "1":
            failures.append(f"a fit of one point: {fits[3.0]}")
        if fits[20.0]["status"] != "3" or not math.isnan(float(fits[20.0]["A_inf"])):
            failures.append(f"a straight line fitted by Eq. (6): {fits[20.0]}")
        if fits[10.0]["status"] != "0":
            failures.append(f"the law's own points not fitted: {fits[10.0]}")
        fit = fits[10.0]
        for name, value in zip(("A_inf", "B", "tau"), truth):
            got, err = float(fit[name]), float(fit[name + "_err"])
            if not abs(got - value) <= 3 * err or not err < 0.5 * value:
                failures.append(f"{name}: {got} +- {err}, expected {value}")
    # The same realizations run one per run, as granpipe writes a run of one point: no
    # sweep.points.csv, the tables without a point prefix, the realization's number in the
    # resolved pipeline (the script read a sweep.points.csv such runs never have).
    parts = [os.path.join(out, name) for name in ("part_a", "part_b", "part_c")]
    for part, replica, source in zip(parts, (0, 1, 1), ("point_000", "point_001", "point_001")):
        os.makedirs(part)
        with open(os.path.join(part, "pipeline.json"), "w") as f:
            json.dump({"source": {"params": {"replica": replica}},
                       "sweep": {"parameters": {"source.params.replica": [replica]}}}, f)
        with open(os.path.join(out, f"{source}.compaction.ageing.csv")) as f:
            write(part, "compaction.ageing.csv", f.read().splitlines()[1:])
    r = subprocess.run([sys.executable, script, parts[0], parts[1]], capture_output=True, text=True)
    whole = rows(os.path.join(out, "pooled.compaction.ageing.csv"))
    if r.returncode != 0 or rows(os.path.join(parts[0], "pooled.compaction.ageing.csv")) != whole:
        failures.append(f"two parts: exit {r.returncode}, {r.stderr!r}")
    r = subprocess.run([sys.executable, script, parts[0], parts[1], parts[2]], capture_output=True, text=True)
    if r.returncode != 2 or r.stderr != (f"{parts[2]}: source.params.replica = 1: expected each "
                                         f"realization once, found it in {parts[1]} too\n"):
        failures.append(f"a realization twice: exit {r.returncode}, {r.stderr!r}")
    # A part of another pipeline (another N: the helper's N = 100 and 200, epsilon 0.05 and
    # 0.5, pooled as four realizations, exit 0) is refused; one of another seed is pooled,
    # and the pooled tables name every part's run.
    other = os.path.join(out, "part_other")
    os.makedirs(other)
    with open(os.path.join(other, "pipeline.json"), "w") as f:
        json.dump({"source": {"params": {"replica": 2, "N": 200}}}, f)
    with open(os.path.join(parts[1], "compaction.ageing.csv")) as f:
        table = f.read().splitlines()[1:]
    write(other, "compaction.ageing.csv", table)
    r = subprocess.run([sys.executable, script, parts[0], other], capture_output=True, text=True)
    if r.returncode != 2 or r.stderr != (f"{other}/pipeline.json: source.params.N: expected the "
                                         f"value of {parts[0]} (parts of one set of "
                                         f"realizations), found 200 against null\n"):
        failures.append(f"a part of another pipeline: exit {r.returncode}, {r.stderr!r}")
    with open(os.path.join(other, "pipeline.json"), "w") as f:
        json.dump({"seed": 99, "source": {"params": {"replica": 2}}}, f)
    with open(os.path.join(other, "compaction.ageing.csv"), "w") as f:
        f.write("# granpipe seed 99\n" + "\n".join(table) + "\n")
    r = subprocess.run([sys.executable, script, parts[0], other], capture_output=True, text=True)
    with open(os.path.join(parts[0], "pooled.compaction.ageing.csv")) as f:
        first_line = f.readline()
    if r.returncode != 0 or "granpipe test + granpipe seed 99" not in first_line:
        failures.append(f"parts of two seeds: exit {r.returncode}, {r.stderr!r}, {first_line!r}")
    # Parts grouped by another swept parameter list its values in another order: their
    # pipeline.json give point 0's eta, which differs, and is no difference of pipelines.
    grouped = []
    for name, replica, etas in (("eta_a", 0, [1e-6, 1e-5]), ("eta_b", 1, [1e-5, 1e-6])):
        part = os.path.join(out, name)
        os.makedirs(part)
        with open(os.path.join(part, "pipeline.json"), "w") as f:
            json.dump({"source": {"params": {"replica": replica, "eta": etas[0]}},
                       "sweep": {"parameters": {"source.params.eta": etas,
                                                "source.params.replica": [replica]}}}, f)
        write(part, "sweep.points.csv", ["point,source.params.eta,source.params.replica"] +
              [f"{k},{eta!r},{replica}" for k, eta in enumerate(etas)])
        for k in range(2):
            write(part, f"point_00{k}.compaction.ageing.csv", table)
        grouped.append(part)
    r = subprocess.run([sys.executable, script, *grouped], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"parts grouped by eta in another order: exit {r.returncode}, {r.stderr!r}")
    os.remove(os.path.join(out, "point_001.compaction.ageing.csv"))
    r = subprocess.run([sys.executable, script, out], capture_output=True, text=True)
    if r.returncode != 2 or "expected the ageing table of source.params.replica = 1, found no file" not in r.stderr:
        failures.append(f"missing table: exit {r.returncode}, {r.stderr!r}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
