"""scripts/plot_tap3d_ageing.py on made-up pooled tables: one curve per waiting time (gid
series-<k>), the collapse of the t_w whose fit is defined beside the master curve of Eq. (6),
and a table without the column A refused in one line."""
import math
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

script = sys.argv[1]
failures = []


def series_ids(path):
    return {g.get("id") for g in ET.parse(path).getroot().iter() if g.get("id", "").startswith("series-")}


with tempfile.TemporaryDirectory() as run:
    laws = {10.0: (0.04, 0.5, 3.0), 100.0: (0.03, 0.4, 8.0), 300.0: (math.nan,) * 3}
    with open(os.path.join(run, "pooled.compaction.ageing.csv"), "w") as f:
        f.write("# made up\ngroup,t_w,t,realizations,A,A_err\n")
        for t_w, (a_inf, b, tau) in laws.items():
            for t in range(0, 200, 5):
                a = a_inf * (1 - 1 / (1 + b * math.log1p(t / tau))) if math.isfinite(a_inf) else 0.01
                f.write(f"all,{t_w},{t},10,{a!r},0.001\n")
    with open(os.path.join(run, "pooled.compaction.ageing_fits.csv"), "w") as f:
        f.write("# made up\ngroup,t_w,points,status,A_inf,A_inf_err,B,B_err,tau,tau_err\n")
        for t_w, (a_inf, b, tau) in laws.items():
            f.write(f"all,{t_w},40,{0 if math.isfinite(a_inf) else 3},{a_inf},0.001,{b},0.01,{tau},0.1\n")
    prefix = os.path.join(run, "fig5")
    r = subprocess.run([sys.executable, script, run, prefix], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"plot: {r.returncode} {r.stderr}")
    else:
        if len(series_ids(prefix + "_scaled.svg")) != 3:
            failures.append(f"scaled: {sorted(series_ids(prefix + '_scaled.svg'))}")
        if len(series_ids(prefix + "_curves.svg")) != 3:
            failures.append(f"curves: {sorted(series_ids(prefix + '_curves.svg'))}")
        if len(series_ids(prefix + "_collapse.svg")) != 3:  # two fits and the master curve
            failures.append(f"collapse: {sorted(series_ids(prefix + '_collapse.svg'))}")
    bad = os.path.join(run, "bad.ageing.csv")
    with open(bad, "w") as f:
        f.write("group,t_w,t\nall,1,1\n")
    r = subprocess.run([sys.executable, script, bad, prefix], capture_output=True, text=True)
    if r.returncode != 2 or not r.stderr.startswith(f"{bad}: expected columns group, t_w, t, A, found no A"):
        failures.append(f"missing column: {r.returncode} {r.stderr}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("plot_tap3d_ageing: three curves, two collapsed beside Eq. (6), a missing column refused")
