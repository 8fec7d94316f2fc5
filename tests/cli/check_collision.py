"""The head-on collision of pipelines/dem_speed_vs_error.json at dt = t_c/50: the `dem` source's
contact time and restitution coefficient within 0.5 % of the linear law's (computed here
independently from Eqs. 9-10: t_c = pi / sqrt(k_n/m_eff - gamma_n^2/4), e = exp(-gamma_n t_c/2));
a run too short for the spheres to meet is refused in one line with exit 2."""
import csv
import math
import os
import subprocess
import sys
import tempfile

granpipe, pipeline = sys.argv[1], sys.argv[2]
kn, gamma_n, mass = 2e5, 42.398, 1.91 * math.pi / 6.0  # the pipeline's values, d = 1
m_eff = mass / 2.0
t_c = math.pi / math.sqrt(kn / m_eff - gamma_n**2 / 4.0)
e = math.exp(-gamma_n * t_c / 2.0)


def run(out, *settings):
    command = [granpipe, pipeline, "--out", out, "--threads", "1", "--quiet"]
    for s in settings:
        command += ["--set", s]
    return subprocess.run(command, capture_output=True, text=True)


failures = []
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "collision")
    r = run(out, f"source.params.dt={0.02 * t_c!r}")
    if r.returncode != 0:
        failures.append(f"exit {r.returncode}: {r.stderr}")
    else:
        with open(os.path.join(out, "collision.scalars.csv")) as f:
            s = {row["name"]: float(row["value"]) for row in csv.DictReader(l for l in f if not l.startswith("#"))}
        if abs(s["contact_time"] / t_c - 1.0) > 0.005 or abs(s["restitution"] / e - 1.0) > 0.005:
            failures.append(f"measured t_c {s['contact_time']} against {t_c}, e {s['restitution']} against {e}")
        if abs(s["contact_time_analytic"] / t_c - 1.0) > 1e-12 or abs(s["restitution_analytic"] / e - 1.0) > 1e-12:
            failures.append(f"analytic t_c {s['contact_time_analytic']} against {t_c}, e {s['restitution_analytic']} against {e}")
        if s["frames_in_contact"] not in (49.0, 50.0, 51.0):
            failures.append(f"{s['frames_in_contact']} frames in contact at dt = t_c/50")
    r = run(os.path.join(tmp, "short"), "source.params.duration=0.01")
    expected = (f"granpipe: {pipeline}: analyzers[0]: collision: 42 frames: expected the two spheres "
                "to collide, got no contact\n")
    if r.returncode != 2 or r.stderr != expected:
        failures.append(f"a run without contact: exit {r.returncode}, {r.stderr!r}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print(f"collision at dt = t_c/50: t_c and e within 0.5 % of {t_c:.6g} and {e:.6g}")
