"""scripts/dem_speed_vs_error.py collision: 5 x 4 granpipe runs of the two-sphere collision, a
table with their errors (within 2 % down to 12.5 steps per contact), the plot with both
series, a second call that runs nothing again, and a point directory left by an interrupted
run refused in one line."""
import csv
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script, granpipe = sys.argv[1], sys.argv[2]
failures = []
with tempfile.TemporaryDirectory() as tmp:
    out, table, plot = os.path.join(tmp, "runs"), os.path.join(tmp, "table.csv"), os.path.join(tmp, "plot.svg")
    command = [sys.executable, script, "collision", "--granpipe", granpipe, "--out", out, "--csv", table, "--plot", plot]
    r = subprocess.run(command, capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        rows = list(csv.DictReader(line for line in open(table) if not line.startswith("#")))
        worst = max(abs(float(row[q])) for row in rows for q in ("contact_time_rel_error", "restitution_rel_error"))
        if len(rows) != 20 or worst > 0.02 or r.stdout.count("\n") != 7:
            failures.append(f"{len(rows)} rows, worst relative error {worst}, stdout {r.stdout}")
        svg = ET.parse(plot).getroot()
        markers = [sum(1 for e in g.iter() if e.tag.endswith("}use"))
                   for g in svg.iter() if g.get("id", "").startswith("series-")]
        if markers != [5, 5]:
            failures.append(f"markers per series: {markers}")
        log = open(os.path.join(out, "cpu_seconds.csv")).read()
        r = subprocess.run(command, capture_output=True, text=True)
        if r.returncode != 0 or open(os.path.join(out, "cpu_seconds.csv")).read() != log or r.stderr:
            failures.append(f"second call: exit {r.returncode}, {r.stderr}")
        # A point cut off mid-run: its directory exists, cpu_seconds.csv does not list it.
        with open(os.path.join(out, "cpu_seconds.csv"), "w") as f:
            f.write("".join(line for line in log.splitlines(True) if not line.startswith("dt_tc_0.08_phase3,")))
        r = subprocess.run(command, capture_output=True, text=True)
        expected = (f"{out}/dt_tc_0.08_phase3: expected no directory for a point not in cpu_seconds.csv, found one "
                    "(an interrupted run?): remove it to run the point again\n")
        if r.returncode != 2 or r.stderr != expected or not os.path.isdir(os.path.join(out, "dt_tc_0.08_phase3")):
            failures.append(f"interrupted point: exit {r.returncode}, {r.stderr!r}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("dem_speed_vs_error.py collision: twenty runs, errors, plot, resume and refusal right")
