"""A report.html as headless Chromium (Debian's `chromium`) sees it: the DOM after loading,
the console's errors, a screenshot. Shared by the checks of report.html."""
import os
import shutil
import subprocess
from html.parser import HTMLParser

SKIP = 77  # ctest's SKIP_RETURN_CODE for these checks


def browser():
    """The Chromium executable, or None (the caller skips with a message)."""
    return shutil.which("chromium") or shutil.which("chromium-browser")


def headless(chromium, profile):
    return [chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
            "--enable-logging=stderr", "--v=0", "--window-size=1000,1600",
            "--user-data-dir=" + profile]


class Figures(HTMLParser):
    """The number of <figure> elements and of <svg> elements in a DOM."""

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


def load(chromium, page, profile):
    """(Figures of the DOM Chromium built from `page`, its console errors)."""
    url = "file://" + os.path.abspath(page)
    dom = subprocess.run(headless(chromium, profile) + ["--dump-dom", url], capture_output=True,
                         text=True, timeout=120)
    return Figures(dom.stdout), console_errors(dom.stderr)


def screenshot(chromium, page, profile, png):
    """Takes a screenshot of `page` into `png`; returns Chromium's stderr."""
    url = "file://" + os.path.abspath(page)
    shot = subprocess.run(headless(chromium, profile) + ["--screenshot=" + png, url],
                          capture_output=True, text=True, timeout=120)
    return shot.stderr
