"""report.html of every shipped pipeline opens in headless Chromium without a console error,
with an SVG in each of its figures. Each pipeline runs at the toy size of toy_runs.json (a
shipped pipeline missing there fails the check, so that a new one is not left out). Skips
(exit 77) with a message when Chromium is absent."""
import glob
import json
import os
import subprocess
import sys
import tempfile

from chromium_page import SKIP, browser, load

exe, pipelines_dir, toy_file = sys.argv[1], sys.argv[2], sys.argv[3]
chromium = browser()
if chromium is None:
    print("SKIP: chromium is not installed (apt-get install chromium)")
    sys.exit(SKIP)
with open(toy_file) as f:
    toy = json.load(f)

failures, pages = [], 0
with tempfile.TemporaryDirectory() as work:
    for path in sorted(glob.glob(os.path.join(pipelines_dir, "*.json"))):
        name = os.path.splitext(os.path.basename(path))[0]
        if name not in toy:
            failures.append(f"{name}: no toy size in {os.path.basename(toy_file)}")
            continue
        out = os.path.join(work, name)
        sets = [arg for value in toy[name] for arg in ("--set", value)]
        run = subprocess.run([exe, path, *sets, "--quiet", "--out", out], capture_output=True,
                             text=True)
        page = os.path.join(out, "report.html")
        if run.returncode != 0 or not os.path.exists(page):
            failures.append(f"{name}: exit {run.returncode}, {run.stderr.strip()[-300:]}")
            continue
        figures, errors = load(chromium, page, os.path.join(work, "profile"))
        pages += 1
        if figures.svgs < figures.figures:
            failures.append(f"{name}: {figures.figures} figures but {figures.svgs} SVGs")
        failures += [f"{name}: console: {line}" for line in errors]
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print(f"report.html of {pages} shipped pipelines: each opens in Chromium, no console error")
