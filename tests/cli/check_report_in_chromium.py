"""report.html in a real browser (Debian's headless Chromium): the page of a toy run loads
without a console error, its DOM holds an SVG per declared plot, and its screenshot is not
blank. Skips (exit 77) with a message when Chromium is absent."""
import os
import subprocess
import sys
import tempfile

from chromium_page import SKIP, browser, load, screenshot

exe, pipeline = sys.argv[1], sys.argv[2]
chromium = browser()
if chromium is None:
    print("SKIP: chromium is not installed (apt-get install chromium)")
    sys.exit(SKIP)
import matplotlib.image  # noqa: E402  (after the skip: only this test needs it)

failures = []
with tempfile.TemporaryDirectory() as work:
    run = os.path.join(work, "run")
    subprocess.run([exe, pipeline, "--set", "source.params.N=64", "--set", "source.params.side=6",
                    "--set", "source.params.taps=3", "--set",
                    'sweep.parameters={"source.params.epsilon": [0.05]}', "--quiet", "--out", run],
                   check=True)
    page, profile = os.path.join(run, "report.html"), os.path.join(work, "profile")
    svgs, errors = load(chromium, page, profile)
    if svgs.figures == 0 or svgs.svgs < svgs.figures:
        failures.append(f"the browser's DOM holds {svgs.figures} figures and {svgs.svgs} SVGs")
    failures += [f"console: {line}" for line in errors]
    png = os.path.join(work, "report.png")
    shot = screenshot(chromium, page, profile, png)
    if not os.path.exists(png):
        failures.append(f"no screenshot: {shot[-500:]}")
    else:
        pixels = matplotlib.image.imread(png)[..., :3]
        inked = (pixels.min(axis=2) < 0.9).mean()  # the share of pixels that are not white
        if inked < 0.02:
            failures.append(f"the screenshot is blank: {inked:.4f} of its pixels inked")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print(f"report.html in Chromium: {svgs.figures} plots, no console error, the page drawn")
