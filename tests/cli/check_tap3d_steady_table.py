"""scripts/tap3d_steady_table.py and plot_tap3d_steady.py on two made-up analysed runs: the
windows' means of <Phi^c> are those of the rows made (exact), epsilon comes from the pipeline
or from RUN=EPSILON, a run without either is refused in one line, --add keeps the rows a table
holds and replaces those of the same epsilon, and the three figures are
drawn (one series per run in the spectra, gid series-<k>). Refused in one line, exit 2, the
run's files unchanged: an output that is a table of a run read, an epsilon that is not a
finite number > 0, a tap of nan, a per-frame table of a header only."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

table_script, plot_script = sys.argv[1], sys.argv[2]
failures = []


def make_run(folder, epsilon, slope, sigma, drift=1e-4):
    """Taps 0..3000 every 10 with phi_c = 0.6 + slope * tap and <Z> falling by `drift` a tap
    on a step down before the steady taps (1500 on); the scalars the table reads."""
    os.makedirs(folder)
    params = {"epsilon": epsilon} if epsilon is not None else {"file": "frames.h5"}
    with open(os.path.join(folder, "pipeline.json"), "w") as f:
        json.dump({"name": "made", "source": {"plugin": "x", "params": params}}, f)
    with open(os.path.join(folder, "stereology.per_frame.csv"), "w") as f:
        f.write("# granpipe test\nframe,tap,phi_c\n")
        for k, tap in enumerate(range(0, 3001, 10)):
            f.write(f"{k},{tap},{0.6 + slope * tap!r}\n")
    with open(os.path.join(folder, "compaction.per_frame.csv"), "w") as f:
        f.write("frame,tap,z_mean\n")
        for k, tap in enumerate(range(0, 3001, 10)):
            f.write(f"{k},{tap},{(20.0 if tap < 1500 else 15.0) - drift * tap!r}\n")
    with open(os.path.join(folder, "compaction.scalars.csv"), "w") as f:
        f.write("name,value,uncertainty,unit\n")
        f.write("phi_b_ss,0.59,0.001,\n")
        f.write(f"z_mean_sigma,{sigma},nan,R\n")
        f.write("spectrum_slope_z_mean,-1.2,0.1,\n")
        f.write("steady_from,1500,nan,taps\n")
    with open(os.path.join(folder, "compaction.spectrum.csv"), "w") as f:
        f.write("frequency,z_mean,phi_b,phi_c\n0.01,1.0,1,1\n0.02,0.25,1,1\n")


def rows_of(path):
    lines = [line.strip().split(",") for line in open(path) if not line.startswith("#")]
    return [dict(zip(lines[0], map(float, r))) for r in lines[1:]]


with tempfile.TemporaryDirectory() as work:
    a, b, c = (os.path.join(work, n) for n in ("a", "b", "c"))
    make_run(a, 0.04, 1e-6, 0.03)
    make_run(b, None, 2e-6, 0.05)
    make_run(c, None, 0.0, 0.05)
    out = os.path.join(work, "table.csv")
    r = subprocess.run([sys.executable, table_script, out, a, b + "=0.09"], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"table: {r.returncode} {r.stderr}")
    else:
        rows = rows_of(out)
        # Taps 1000..1990 every 10: mean tap 1495; 2000..2990: 2495; the last tap 3000.
        expected = [(0.04, 1e-6), (0.09, 2e-6)]
        for row, (eps, slope) in zip(rows, expected):
            want = {"epsilon": eps, "phi_c_taps_1000_2000": 0.6 + slope * 1495,
                    "phi_c_taps_2000_3000": 0.6 + slope * 2495, "phi_c_last": 0.6 + slope * 3000,
                    "last_tap": 3000, "z_mean_sigma": 0.03 if eps == 0.04 else 0.05,
                    "z_mean_drift_per_1000_taps": -0.1}
            for name, value in want.items():
                if abs(row.get(name, float("nan")) - value) > 1e-6 * abs(value):
                    failures.append(f"epsilon {eps}: {name} {row.get(name)} against {value}")
        # A straight line over the steady taps: nothing about it (the step before them left out).
        if any(abs(row.get("z_mean_sigma_about_drift", 1.0)) > 1e-9 for row in rows):
            failures.append(f"fluctuation about the drift: {[r.get('z_mean_sigma_about_drift') for r in rows]}")
        if len(rows) != 2 or "phi_c_taps_3000_4000" in rows[0]:
            failures.append(f"rows {rows}")
    # --add keeps the rows of runs whose folders are gone and replaces a row of the same
    # epsilon: b again as 0.09 with c's numbers, and c as 0.16.
    shutil.copy(out, out + ".before")
    r = subprocess.run([sys.executable, table_script, out, "--add", c + "=0.09", c + "=0.16"],
                       capture_output=True, text=True)
    before, after = rows_of(out + ".before"), rows_of(out) if r.returncode == 0 else []
    if (r.returncode != 0 or [row["epsilon"] for row in after] != [0.04, 0.09, 0.16]
            or after[0] != before[0] or after[1]["phi_c_last"] != 0.6):
        failures.append(f"--add: {r.returncode} {r.stderr} {after}")
    with open(out) as f:
        if not f.readline().endswith(f" then --add {c}=0.09 {c}=0.16\n"):
            failures.append("--add: the provenance line does not name the runs added")
    shutil.copy(out + ".before", out)
    r = subprocess.run([sys.executable, table_script, out, c], capture_output=True, text=True)
    if r.returncode != 2 or not r.stderr.startswith(f"{c}/pipeline.json: expected source.params.epsilon"):
        failures.append(f"no epsilon: {r.returncode} {r.stderr}")
    # A per-frame table where the scalars should be: refused, naming the file and its columns.
    shutil.copy(os.path.join(c, "compaction.per_frame.csv"), os.path.join(c, "compaction.scalars.csv"))
    r = subprocess.run([sys.executable, table_script, out, c + "=0.01"], capture_output=True, text=True)
    if r.returncode != 2 or r.stderr.strip() != (
            f"{c}/compaction.scalars.csv: expected the columns name,value,uncertainty, found frame,tap,z_mean"):
        failures.append(f"not a scalars table: {r.returncode} {r.stderr}")
    refusals = {
        "an output in a run": ([os.path.join(a, "compaction.scalars.csv"), a],
                               f"{a}/compaction.scalars.csv: expected an output outside the run "
                               f"folders read ({a}), got a file in {a}"),
        "no output folder": ([os.path.join(work, "no", "t.csv"), a],
                             f"{work}/no/t.csv: expected an output in an existing folder, got no "
                             f"folder {work}/no"),
        "epsilon < 0": ([out, a + "=-0.05"], f"{a}=-0.05: expected a finite number > 0 after '=', "
                                            "found '-0.05'"),
        "epsilon nan": ([out, a + "=nan"], f"{a}=nan: expected a finite number > 0 after '=', "
                                          "found 'nan'"),
    }
    for what, (args, message) in refusals.items():
        shutil.copytree(a, a + ".kept")
        r = subprocess.run([sys.executable, table_script, *args], capture_output=True, text=True)
        changed = subprocess.run(["diff", "-r", a, a + ".kept"], capture_output=True).returncode
        shutil.rmtree(a + ".kept")
        if r.returncode != 2 or r.stderr != message + "\n" or changed:
            failures.append(f"{what}: {r.returncode} {r.stderr} run changed: {bool(changed)}")
    stereology = os.path.join(c, "stereology.per_frame.csv")
    with open(stereology) as f:
        lines = f.readlines()
    broken = {"a tap of nan": (lines[:3] + ["2,nan,0.6\n"] + lines[4:],
                               f"{stereology}: data row 2, column tap: expected a finite number, found nan"),
              "a header only": (lines[:2], f"{stereology}: expected rows of tap, found only a header")}
    for what, (text, message) in broken.items():
        with open(stereology, "w") as f:
            f.writelines(text)
        r = subprocess.run([sys.executable, table_script, out, c + "=0.01"], capture_output=True, text=True)
        if r.returncode != 2 or r.stderr != message + "\n":
            failures.append(f"{what}: {r.returncode} {r.stderr}")
    prefix = os.path.join(work, "fig")
    r = subprocess.run([sys.executable, plot_script, out, prefix, a + "=first", b + "=second"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"plot: {r.returncode} {r.stderr}")
    else:
        for kind, series in (("phi_c", 2), ("sigma", 3), ("spectra", 2)):
            root = ET.parse(f"{prefix}_{kind}.svg").getroot()
            drawn = {g.get("id") for g in root.iter() if g.get("id", "").startswith("series-")}
            if len(drawn) != series:
                failures.append(f"{kind}: series {sorted(drawn)}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("tap3d_steady_table: windows exact, epsilon from the pipeline or the argument, refusals; three figures")
