"""scripts/plot_tap3d_compaction.py on a toy run of tap3d_compaction.json: three SVGs with one
line per epsilon (gid series-<k>), the fit table with every epsilon's parameters; the laws it
draws equal their values at t = 0 (Eq. 3: X_inf - dX_inf; Eq. 4: <Z>_0); a folder that is no
run is refused in one line, and so are an OUT_PREFIX that would replace a run's own table and
a run folder given where OUT_PREFIX was forgotten."""
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script, exe, pipeline = sys.argv[1], sys.argv[2], sys.argv[3]
sys.path.insert(0, os.path.dirname(script))
import plot_tap3d_compaction as plot  # noqa: E402

failures = []
p3 = {"X_inf": 0.6, "dX_inf": 0.05, "B": 2.0, "tau": 3.0}
p4 = {"Z_inf": 14.0, "Z_0": 15.0, "B": 2.0, "tau": 3.0}
if abs(plot.eq3(0.0, p3) - 0.55) > 1e-15 or abs(plot.eq4(0.0, p4) - 15.0) > 1e-12:
    failures.append(f"laws at t = 0: {plot.eq3(0.0, p3)}, {plot.eq4(0.0, p4)}")
if not plot.eq3(1e6, p3) < 0.6 or not plot.eq4(1e6, p4) > 14.0:
    failures.append("the laws cross their limits")
with tempfile.TemporaryDirectory() as work:
    run = os.path.join(work, "run")
    subprocess.run([exe, pipeline, "--set", "source.params.N=64", "--set", "source.params.side=6",
                    "--set", "source.params.taps=3", "--quiet", "--out", run], check=True)
    prefix = os.path.join(work, "fig2")
    r = subprocess.run([sys.executable, script, run, prefix], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        for suffix in ("phi_b", "phi_c", "z"):
            root = ET.parse(f"{prefix}_{suffix}.svg").getroot()
            lines = {g.get("id") for g in root.iter() if g.get("id", "").startswith("series-")}
            if lines != {"series-0", "series-1", "series-2"}:
                failures.append(f"{suffix}: lines {sorted(lines)}")
        with open(f"{prefix}.csv") as f:
            rows = [line.split(",") for line in f.read().splitlines()[1:]]
        for eps in ("0.005", "0.05", "0.15"):
            fitted = {(r[1], r[2]) for r in rows if r[0] == f"ε = {eps}"}
            if ("eq3_phi_b", "tau") not in fitted or ("eq4_z_mean", "B") not in fitted:
                failures.append(f"epsilon {eps}: {sorted(fitted)[:4]}")
    # A reprocessing of saved frames has no epsilon of its own: named on the command line.
    saved = os.path.join(work, "saved")
    subprocess.run([exe, pipeline, "--set", "source.params.N=64", "--set", "source.params.side=6",
                    "--set", "source.params.taps=3", "--set",
                    'sweep.parameters={"source.params.epsilon": [0.05]}', "--set",
                    "output.save_frames=true", "--quiet", "--out", saved], check=True)
    reprocess = os.path.join(work, "reprocess.json")
    with open(reprocess, "w") as f:
        json.dump({"name": "reprocess", "seed": 1,
                   "source": {"plugin": "h5md",
                              "params": {"file": os.path.join(saved, "frames.h5")}},
                   "analyzers": [{"plugin": "stereology", "name": "stereology"},
                                 {"plugin": "compaction", "name": "compaction"}]}, f)
    single = os.path.join(work, "single")
    subprocess.run([exe, reprocess, "--quiet", "--out", single], check=True)
    r = subprocess.run([sys.executable, script, run, f"{single}=joined parts", prefix],
                       capture_output=True, text=True)
    with open(f"{prefix}.csv") as f:
        names = {line.split(",")[0] for line in f.read().splitlines()[1:]}
    if r.returncode != 0 or "joined parts" not in names or "ε = 0.15" not in names:
        failures.append(f"labelled run: {r.returncode} {r.stderr} {sorted(names)}")
    # The prefix of a run's per_frame table: its tables are the input, never replaced.
    per_frame = os.path.join(single, "compaction.per_frame.csv")
    with open(per_frame, "rb") as f:
        kept = f.read()
    r = subprocess.run([sys.executable, script, single, per_frame[:-len(".csv")]],
                       capture_output=True, text=True)
    with open(per_frame, "rb") as f:
        unchanged = f.read() == kept
    if r.returncode != 2 or not unchanged or r.stderr != (
            f"{per_frame}: expected an output outside the run folders read ({single}), "
            f"got a file in {single}\n"):
        failures.append(f"a run's table as the output: {r.returncode} {r.stderr} unchanged {unchanged}")
    # OUT_PREFIX forgotten: the last run folder is no prefix.
    r = subprocess.run([sys.executable, script, run, single], capture_output=True, text=True)
    if r.returncode != 2 or r.stderr != (f"{single}: expected OUT_PREFIX (the last argument), the "
                                         "start of the outputs' path, got a folder\n"):
        failures.append(f"OUT_PREFIX forgotten: {r.returncode} {r.stderr}")
    empty = os.path.join(work, "empty")
    os.makedirs(empty)
    r = subprocess.run([sys.executable, script, empty, prefix], capture_output=True, text=True)
    if r.returncode != 2 or "pipeline.json: expected the pipeline of a granpipe run" not in r.stderr:
        failures.append(f"not a run: {r.returncode} {r.stderr}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("plot_tap3d_compaction: a line per epsilon in each figure, the fit table, the laws at t = 0")
