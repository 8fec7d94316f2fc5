"""scripts/speed_vs_error.py on a hand-made sweep: deviations from the finest point of each
group, string parameters named, the table written and the plot drawn with one marker per
point other than the reference."""
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
    rows = list(csv.DictReader(open(os.path.join(out, "speed_vs_error.csv"))))
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
print("speed against error: deviations from the finest point of each group are right")
