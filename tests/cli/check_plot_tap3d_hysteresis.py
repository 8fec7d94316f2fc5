"""scripts/plot_tap3d_hysteresis.py redraws Fig. 4 from the kept tables: one line per leg (gid
series-<k>), one black square per steady-state point; a missing column is refused in one line."""
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script, data = sys.argv[1], sys.argv[2]
by_leg = os.path.join(data, "tap3d_hysteresis.by_leg.csv")
points = os.path.join(data, "tap3d_steady_states.sweep.points.csv")
failures = []
with tempfile.TemporaryDirectory() as out:
    svg = os.path.join(out, "fig4.svg")
    r = subprocess.run([sys.executable, script, by_leg, points, svg], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        root = ET.parse(svg).getroot()
        lines = {g.get("id") for g in root.iter() if g.get("id", "").startswith("series-")}
        squares = max(sum(1 for e in g.iter() if e.tag.endswith("}use"))
                      for g in root.iter() if g.get("id") == "reference")
        if lines != {"series-0", "series-1", "series-2"} or squares != 8:
            failures.append(f"lines {sorted(lines)}, reference markers {squares}")
    # The paper-size ramp beside the steady-state table of scripts/tap3d_steady_table.py.
    paper_points = os.path.join(data, "tap3d_steady_paper.csv")
    r = subprocess.run([sys.executable, script, os.path.join(data, "tap3d_ramp_100", "stereology.by_leg.csv"),
                        paper_points, svg], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        root = ET.parse(svg).getroot()
        squares = max(sum(1 for e in g.iter() if e.tag.endswith("}use"))
                      for g in root.iter() if g.get("id") == "reference")
        with open(paper_points) as f:
            rows = sum(1 for line in f if line[:1].isdigit())
        if squares != rows:
            failures.append(f"paper table: {squares} reference markers for {rows} rows")
    r = subprocess.run([sys.executable, script, points, points, svg], capture_output=True, text=True)
    if r.returncode != 2 or not r.stderr.startswith(f"{points}: expected a column branch"):
        failures.append(f"missing column: {r.returncode} {r.stderr}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("plot_tap3d_hysteresis: three legs and eight steady states drawn, the paper-size ramp beside its "
      "steady-state table, a missing column refused")
