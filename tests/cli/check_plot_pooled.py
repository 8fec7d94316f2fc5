"""scripts/plot_pooled.py redraws a kept pooled table: one line per branch (gid series-<k>) and
the reference points (gid reference, one marker each); a missing column is refused in one line."""
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script, data = sys.argv[1], sys.argv[2]
table = os.path.join(data, "tap2d_slow_cooling.pooled.packing.by_ramp.csv")
reference = os.path.join(data, "tap2d_layered_N500.pooled.points.csv")
failures = []
with tempfile.TemporaryDirectory() as out:
    svg = os.path.join(out, "phi.svg")
    r = subprocess.run([sys.executable, script, table, "--plot", "phi", "--reference", reference,
                        "--column", "packing.phi", "--out", svg], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        root = ET.parse(svg).getroot()
        lines = {g.get("id") for g in root.iter() if g.get("id", "").startswith("series-")}
        # errorbar gives the gid to the data line, the bars and the caps: count the largest group.
        squares = max(sum(1 for e in g.iter() if e.tag.endswith("}use"))
                      for g in root.iter() if g.get("id") == "reference")
        if lines != {"series-0", "series-1"} or squares != 6:
            failures.append(f"lines {sorted(lines)}, reference markers {squares}")
    r = subprocess.run([sys.executable, script, table, "--plot", "rho", "--out", svg], capture_output=True, text=True)
    if r.returncode != 2 or r.stderr != f"{table}: expected a number in column rho, found None\n":
        failures.append(f"missing column: {r.returncode} {r.stderr}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("plot_pooled: branches and reference points drawn, a missing column refused")
