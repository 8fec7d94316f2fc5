"""scripts/plot_tap3d_fig8.py on a toy run of tap3d_profiles.json: two SVGs with a line per run
(gid series-<k>, log tap axis), the CSV's rows the run's own delta_lateral and delta_central at
the taps it names; a folder that is no run refused in one line."""
import csv
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script, exe, pipeline = sys.argv[1], sys.argv[2], sys.argv[3]
failures = []
with tempfile.TemporaryDirectory() as work:
    run = os.path.join(work, "run")
    # 10 R wide: a central zone beside the two lateral bands of 3.5 R.
    subprocess.run([exe, pipeline, "--set", "source.params.N=150", "--set", "source.params.side=10",
                    "--set", "source.params.taps=12", "--set", "source.params.save_every=1",
                    "--quiet", "--no-report", "--out", run], check=True)
    prefix = os.path.join(work, "fig8")
    r = subprocess.run([sys.executable, script, run, f"{run}=again", prefix],
                       capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        for suffix in ("lateral", "central"):
            root = ET.parse(f"{prefix}_{suffix}.svg").getroot()
            lines = {g.get("id") for g in root.iter() if g.get("id", "").startswith("series-")}
            if lines != {"series-0", "series-1"}:
                failures.append(f"{suffix}: lines {sorted(lines)}")
        with open(os.path.join(run, "stereology.per_frame.csv")) as f:
            frames = list(csv.DictReader(line for line in f if not line.startswith("#")))
        by_tap = {float(r["tap"]): r for r in frames}
        with open(f"{prefix}.csv") as f:
            rows = list(csv.DictReader(f))
        taps = [float(r["tap"]) for r in rows if r["run"] == "again"]
        if taps != [1.0, 10.0, 12.0]:
            failures.append(f"table taps {taps}, expected 1, 10 and the last, 12")
        for r in rows:
            want = by_tap[float(r["tap"])]
            if (float(r["delta_lateral"]), float(r["delta_central"])) != (
                    float(want["delta_lateral"]), float(want["delta_central"])):
                failures.append(f"tap {r['tap']}: {r} against {want}")
    empty = os.path.join(work, "empty")
    os.makedirs(empty)
    r = subprocess.run([sys.executable, script, empty, prefix], capture_output=True, text=True)
    if r.returncode != 2 or "pipeline.json: expected the pipeline of a granpipe run" not in r.stderr:
        failures.append(f"not a run: {r.returncode} {r.stderr}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("plot_tap3d_fig8: a line per run in both figures, the table the run's own values")
