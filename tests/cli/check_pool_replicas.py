"""scripts/pool_replicas.py on hand-made replicas: the pooled value is the mean of the replica
means and its error the standard error across replicas; a row only one replica has keeps that
run's own error; frames add up; points of other swept values stay in their own group; replicas
with different columns are refused; the table `points` pools the scalars of sweep.points.csv and
keeps the swept values as columns; missing or corrupt tables, a missing pipeline.json, and a
sweep.points.csv with a point twice, rows of too few or too many cells, no point column or no
rows are refused in one line with exit code 2, leaving no pooled table."""
import csv
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script = sys.argv[1]


def write(out, name, lines):
    with open(os.path.join(out, name), "w") as f:
        f.write("# granpipe test\n" + "\n".join(lines) + "\n")


def run(out, table="packing.by_ramp", plot="phi"):
    return subprocess.run([sys.executable, script, out, "--table", table, "--plot", plot],
                          capture_output=True, text=True)


failures = []
with tempfile.TemporaryDirectory() as out:
    with open(os.path.join(out, "pipeline.json"), "w") as f:
        json.dump({"sweep": {"parameters": {"source.params.N": [100, 200], "source.params.replica": [0, 1]}}}, f)
    write(out, "sweep.points.csv", ["point,source.params.N,source.params.replica,packing.phi,packing.phi_err",
                                    "0,100,0,0.80,0.01", "1,100,1,0.84,0.01", "2,200,0,0.7,0.01", "3,200,1,0.7,0.01"])
    header = "branch,amplitude,frames,phi,phi_err"
    write(out, "point_000.packing.by_ramp.csv", [header, "1,1.5,10,0.80,0.01", "2,1.5,10,0.70,0.02"])
    write(out, "point_001.packing.by_ramp.csv", [header, "1,1.5,12,0.84,0.03"])
    write(out, "point_002.packing.by_ramp.csv", [header, "1,1.5,10,0.50,0.01"])
    write(out, "point_003.packing.by_ramp.csv", [header, "1,1.5,10,0.50,0.01"])
    r = run(out)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        rows = list(csv.DictReader(line for line in open(os.path.join(out, "pooled.packing.by_ramp.csv"))
                                   if not line.startswith("#")))
        got = {(row["group"], row["branch"]): row for row in rows}
        a = got[("N=100", "1.0")]
        # mean of 0.80 and 0.84; standard error across two replicas = |0.84 - 0.80| / 2
        if abs(float(a["phi"]) - 0.82) > 1e-12 or abs(float(a["phi_err"]) - 0.02) > 1e-12 or float(a["frames"]) != 22:
            failures.append(f"pooled row {a}")
        b = got[("N=100", "2.0")]
        if float(b["replicas"]) != 1 or abs(float(b["phi_err"]) - 0.02) > 1e-12:
            failures.append(f"single-replica row {b}")
        c = got[("N=200", "1.0")]
        if abs(float(c["phi"]) - 0.5) > 1e-12 or float(c["phi_err"]) != 0.0:
            failures.append(f"second group {c}")
        # One line per branch and group, each with the gid series-<k> (scripts/charts.py).
        svg = os.path.join(out, "pooled.packing.by_ramp.svg")
        lines = {g.get("id") for g in ET.parse(svg).getroot().iter() if g.get("id", "").startswith("series-")} \
            if os.path.exists(svg) else set()
        if len(rows) != 3 or len(lines) != 3:
            failures.append(f"{len(rows)} rows, lines drawn: {sorted(lines)}")
    r = run(out, "points", "packing.phi")
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        rows = list(csv.DictReader(line for line in open(os.path.join(out, "pooled.points.csv"))
                                   if not line.startswith("#")))
        got = {row["source.params.N"]: row for row in rows}
        a, b = got.get("100.0"), got.get("200.0")
        if (len(rows) != 2 or a is None or b is None or abs(float(a["packing.phi"]) - 0.82) > 1e-12
                or abs(float(a["packing.phi_err"]) - 0.02) > 1e-12 or float(a["replicas"]) != 2
                or abs(float(b["packing.phi"]) - 0.7) > 1e-12 or float(b["packing.phi_err"]) != 0.0):
            failures.append(f"pooled points {rows}")
        if not os.path.exists(os.path.join(out, "pooled.points.svg")):
            failures.append("pooled.points.svg not written")
    os.rename(os.path.join(out, "pipeline.json"), os.path.join(out, "kept.json"))
    r = run(out)
    if r.returncode != 2 or r.stderr != (f"{out}/pipeline.json: expected the pipeline of a granpipe run, "
                                         "found none: No such file or directory\n"):
        failures.append(f"missing pipeline.json: {r.returncode} {r.stderr}")
    os.rename(os.path.join(out, "kept.json"), os.path.join(out, "pipeline.json"))
    write(out, "point_003.packing.by_ramp.csv", ["branch,amplitude,frames,rho,rho_err", "1,1.5,10,0.50,0.01"])
    r = run(out)
    expected = (f"{out}/point_003.packing.by_ramp.csv: expected the columns of the replica "
                f"{out}/point_002.packing.by_ramp.csv, ['branch', 'amplitude', 'frames', 'phi', 'phi_err'], "
                "found ['branch', 'amplitude', 'frames', 'rho', 'rho_err']\n")
    if r.returncode != 2 or r.stderr != expected:
        failures.append(f"mismatched columns accepted: {r.returncode} {r.stderr}")
    # Missing and corrupt tables get one line naming the file and exit 2, not a traceback.
    os.remove(os.path.join(out, "sweep.points.csv"))
    r = run(out)
    if r.returncode != 2 or r.stderr != (f"{out}/sweep.points.csv: expected a granpipe table, found none: "
                                         "No such file or directory (a run of one point writes none)\n"):
        failures.append(f"missing sweep.points.csv: {r.returncode} {r.stderr}")
    write(out, "sweep.points.csv", ["point,source.params.N,packing.phi", "0,100,nan?"])
    r = run(out)
    if r.returncode != 2 or r.stderr != (f"{out}/sweep.points.csv: data row 1: expected numbers, "
                                         "found ['0', '100', 'nan?']\n"):
        failures.append(f"corrupt sweep.points.csv: {r.returncode} {r.stderr}")
    # Tables of points that are not one row a point: refused before a pooled table is written.
    header = "point,source.params.N,source.params.replica,packing.phi,packing.phi_err"
    broken = {
        "a point twice": ([header, "0,100,0,0.80,0.01", "1,100,1,0.84,0.01", "0,200,0,0.7,0.01"],
                          "data rows 1 and 3: expected each point once, found point 0 in both"),
        "a row too short": ([header, "0,100,0,0.80,0.01", "1,100,1,0.84"],
                            "data row 2: expected 5 cells (the header's), found 4"),
        "a row too long": ([header, "0,100,0,0.80,0.01,7", "1,100,1,0.84,0.01"],
                           "data row 1: expected 5 cells (the header's), found 6"),
        "no point column": ([header.replace("point,", "index,"), "0,100,0,0.80,0.01"],
                            "expected a column point, found ['index', 'source.params.N', "
                            "'source.params.replica', 'packing.phi']..."),
        "a header only": ([header], "expected rows of sweep points, found only a header"),
        # A NaN point number ended in a traceback (ValueError from int()).
        "a point not a number": ([header, "0,100,0,0.80,0.01", "nan,100,1,0.84,0.01"],
                                 "data row 2, column point: expected a point number, found nan"),
        "a point not whole": ([header, "0.5,100,0,0.80,0.01"],
                              "data row 1, column point: expected a point number, found 0.5"),
    }
    for what, (lines, message) in broken.items():
        for name in os.listdir(out):
            if name.startswith("pooled.points"):
                os.remove(os.path.join(out, name))
        write(out, "sweep.points.csv", lines)
        r = run(out, "points", "packing.phi")
        left = [n for n in os.listdir(out) if n.startswith("pooled.points")]
        if r.returncode != 2 or r.stderr != f"{out}/sweep.points.csv: {message}\n" or left:
            failures.append(f"{what}: {r.returncode} {r.stderr} left {left}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("pool_replicas: means, errors across replicas, groups and frames are right")
