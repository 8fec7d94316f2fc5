"""scripts/plot_pores_fig10.py on a toy run of pores_compaction.json: one line per tap asked
(the nearest saved frame's) in both figures, a table row per tap whose parts of nu add up; a
results file without the pores tables is refused in one line, and so are a TAP that is no
number, an OUT_PREFIX in no existing folder and one that would replace the results read."""
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script, exe, pipeline, lattice = sys.argv[1:5]
failures = []
with tempfile.TemporaryDirectory() as work:
    run = os.path.join(work, "run")
    subprocess.run([exe, pipeline, "--set", "source.params.N=200", "--set", "source.params.side=8",
                    "--set", "source.params.taps=4", "--set", "analyzers[0].params.height=6",
                    "--quiet", "--out", run], check=True)
    prefix = os.path.join(work, "fig10")
    r = subprocess.run([sys.executable, script, os.path.join(run, "results.h5"), prefix, "0", "1", "4"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(r.stderr)
    else:
        for suffix in ("xi3P", "rho_v"):
            root = ET.parse(f"{prefix}_{suffix}.svg").getroot()
            lines = {g.get("id") for g in root.iter() if g.get("id", "").startswith("series-")}
            if lines != {"series-0", "series-1", "series-2"}:
                failures.append(f"{suffix}: lines {sorted(lines)}")
        with open(f"{prefix}.csv") as f:
            rows = [[float(x) for x in line.split(",")] for line in f.read().splitlines()[1:]]
        if [r[0] for r in rows] != [0, 1, 4] or any(abs(r[1] - r[2] - r[3]) > 1e-5 for r in rows):
            failures.append(f"table {rows}")
    results = os.path.join(run, "results.h5")
    refusals = {
        "a TAP of letters": ([results, prefix, "abc"], "TAP 'abc': expected a whole number of taps "
                             "(usage: plot_pores_fig10.py RESULTS.h5 OUT_PREFIX [TAP...])"),
        "no output folder": ([results, os.path.join(work, "nodir", "fig")],
                             f"{work}/nodir/fig_xi3P.svg: expected an output in an existing folder, "
                             f"got no folder {work}/nodir"),
        "the results replaced": ([results, os.path.join(run, "results")],
                                 f"{run}/results.csv: expected an output outside the run folders "
                                 f"read ({run}), got a file in {run}"),
    }
    with open(os.path.join(run, "results.csv"), "w") as f:  # a file of the run folder read
        f.write("kept\n")
    for what, (args, message) in refusals.items():
        r = subprocess.run([sys.executable, script, *args], capture_output=True, text=True)
        if r.returncode != 2 or r.stderr != message + "\n":
            failures.append(f"{what}: {r.returncode} {r.stderr}")
    other = os.path.join(work, "lattice")
    subprocess.run([exe, lattice, "--quiet", "--out", other], check=True)
    results = os.path.join(other, "results.h5")
    r = subprocess.run([sys.executable, script, results, prefix], capture_output=True, text=True)
    if r.returncode != 2 or not r.stderr.startswith(f"{results}: expected the pores analyzer's"):
        failures.append(f"other results: {r.returncode} {r.stderr}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("plot_pores_fig10: a line per tap in both figures, the table, other results refused")
