"""report.html in a real browser (Debian's headless Chromium): the page of a toy run loads
without a console error, its DOM holds an SVG per declared plot, and its screenshot is not
blank. Skips (exit 77) with a message when Chromium is absent."""
import os
import shutil
import subprocess
import sys
import tempfile
from html.parser import HTMLParser

exe, pipeline = sys.argv[1], sys.argv[2]
SKIP = 77
browser = shutil.which("chromium") or shutil.which("chromium-browser")
if browser is None:
    print("SKIP: chromium is not installed (apt-get install chromium)")
    sys.exit(SKIP)
import matplotlib.image  # noqa: E402  (after the skip: only this test needs it)

HEADLESS = [browser, "--headless=new", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
            "--enable-logging=stderr", "--v=0", "--window-size=1000,1600"]


class Svgs(HTMLParser):
    def __init__(self, dom):
        super().__init__()
        self.figures = self.svgs = 0
        self.feed(dom)

    def handle_starttag(self, tag, attrs):
        self.figures += tag == "figure"
        self.svgs += tag == "svg"


def console_errors(log):
    return [line for line in log.splitlines()
            if "CONSOLE" in line or "Uncaught" in line or "ERROR:" in line and "file://" in line]


failures = []
with tempfile.TemporaryDirectory() as work:
    run = os.path.join(work, "run")
    subprocess.run([exe, pipeline, "--set", "source.params.N=64", "--set", "source.params.side=6",
                    "--set", "source.params.taps=3", "--set",
                    'sweep.parameters={"source.params.epsilon": [0.05]}', "--quiet", "--out", run],
                   check=True)
    page = "file://" + os.path.abspath(os.path.join(run, "report.html"))
    profile = ["--user-data-dir=" + os.path.join(work, "profile")]
    dom = subprocess.run(HEADLESS + profile + ["--dump-dom", page], capture_output=True,
                         text=True, timeout=120)
    svgs = Svgs(dom.stdout)
    if svgs.figures == 0 or svgs.svgs < svgs.figures:
        failures.append(f"the browser's DOM holds {svgs.figures} figures and {svgs.svgs} SVGs")
    failures += [f"console: {line}" for line in console_errors(dom.stderr)]
    png = os.path.join(work, "report.png")
    shot = subprocess.run(HEADLESS + profile + ["--screenshot=" + png, page], capture_output=True,
                          text=True, timeout=120)
    if not os.path.exists(png):
        failures.append(f"no screenshot: {shot.stderr[-500:]}")
    else:
        pixels = matplotlib.image.imread(png)[..., :3]
        inked = (pixels.min(axis=2) < 0.9).mean()  # the share of pixels that are not white
        if inked < 0.02:
            failures.append(f"the screenshot is blank: {inked:.4f} of its pixels inked")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print(f"report.html in Chromium: {svgs.figures} plots, no console error, the page drawn")
