"""scripts/speed_vs_error.py on a hand-made sweep: deviations from the finest point of each
group, string parameters named, the table written (after the sweep's provenance line) and
the plot drawn with one marker per point other than the reference; a sweep without rows
refused, the table of an earlier call left whole."""
import csv
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script = sys.argv[1]
with tempfile.TemporaryDirectory() as out:
    with open(os.path.join(out, "pipeline.json"), "w") as f:
        json.dump({"sweep": {"parameters": {"source.params.delta": [0.1, 0.01],
                                            "source.params.move_order": ["sweeps", "random"]}}}, f)
    with open(os.path.join(out, "sweep.points.csv"), "w") as f:
        f.write("# granpipe test\n")
        f.write("point,source.params.delta,source.params.move_order,packing.phi,packing.phi_err,source.seconds\n")
        f.write("0,0.1,0,0.80,0.001,1.0\n1,0.1,1,0.70,0.001,1.5\n2,0.01,0,0.84,0.001,9.0\n3,0.01,1,0.75,0.001,12.0\n")
    subprocess.run([sys.executable, script, out, "--knob", "source.params.delta", "--time", "source.seconds",
                    "--quantity", "packing.phi"], check=True, capture_output=True)
    table = os.path.join(out, "speed_vs_error.csv")
    with open(table) as f:
        first = f.readline()
        rows = list(csv.DictReader(f))
    if first != "# granpipe test speed against error by scripts/speed_vs_error.py\n":
        print("FAIL provenance line", first)
        sys.exit(1)
    got = {(r["group"], float(r["source.params.delta"])): float(r["packing.phi_deviation"]) for r in rows}
    expected = {("move_order=sweeps", 0.1): 0.04, ("move_order=sweeps", 0.01): 0.0,
                ("move_order=random", 0.1): 0.05, ("move_order=random", 0.01): 0.0}
    bad = [k for k in expected if abs(got.get(k, -1) - expected[k]) > 1e-12]
    # scripts/charts.py gives each series the gid series-<k>; a marker is a <use> inside it.
    svg = ET.parse(os.path.join(out, "speed_vs_error.svg")).getroot()
    markers = sum(1 for g in svg.iter() if g.get("id", "").startswith("series-")
                  for e in g.iter() if e.tag.endswith("}use"))
    if bad or markers != 2:
        print("FAIL", got, markers)
        sys.exit(1)
    # A header without rows emptied the table of the call before, then crashed (IndexError).
    before = open(table).read()
    with open(os.path.join(out, "sweep.points.csv"), "w") as f:
        f.write("point,source.params.delta,source.params.move_order,packing.phi,source.seconds\n")
    r = subprocess.run([sys.executable, script, out, "--knob", "source.params.delta", "--time",
                        "source.seconds", "--quantity", "packing.phi"], capture_output=True, text=True)
    if (r.returncode != 2 or r.stderr != f"{out}/sweep.points.csv: expected rows of sweep points, "
            "found only a header\n" or open(table).read() != before):
        print("FAIL no rows", r.returncode, r.stderr)
        sys.exit(1)
# --pool: two replicas, each against its own finest point, averaged per knob value.
with tempfile.TemporaryDirectory() as out:
    with open(os.path.join(out, "pipeline.json"), "w") as f:
        json.dump({"sweep": {"parameters": {"source.params.eta": [1e-3, 1e-6],
                                            "source.params.replica": [0, 1]}}}, f)
    with open(os.path.join(out, "sweep.points.csv"), "w") as f:
        f.write("# granpipe test\n")
        f.write("point,source.params.eta,source.params.replica,phi,source.seconds\n")
        f.write("0,0.001,0,0.50,1.0\n1,0.001,1,0.54,3.0\n2,1e-06,0,0.58,10.0\n3,1e-06,1,0.57,20.0\n")
    subprocess.run([sys.executable, script, out, "--knob", "source.params.eta", "--time", "source.seconds",
                    "--quantity", "phi", "--pool", "source.params.replica"], check=True, capture_output=True)
    with open(os.path.join(out, "speed_vs_error.csv")) as f:
        f.readline()
        rows = {float(r["source.params.eta"]): r for r in csv.DictReader(f)}
    coarse = rows[1e-3]
    # Deviations |0.50 - 0.58| = 0.08 and |0.54 - 0.57| = 0.03: mean 0.055, standard error 0.025.
    if (abs(float(coarse["phi_deviation"]) - 0.055) > 1e-12 or abs(float(coarse["seconds"]) - 2.0) > 1e-12
            or abs(float(coarse["phi_deviation_err"]) - 0.025) > 1e-12 or coarse["group"] != "all"
            or float(rows[1e-6]["phi_deviation"]) != 0.0):
        print("FAIL pooled", rows)
        sys.exit(1)
print("speed against error: deviations from the finest point of each group, and pooled, are right")
