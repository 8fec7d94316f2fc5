"""report.html at the end of a run: the provenance with the time per stage, each declared
plot drawn (an SVG with the declared axis labels, points in it), the scalars and fits, the
last saved frame drawn; a sweep's plots with one line per point; the pipeline's "report"
section (a result against the swept parameter, the paper's values over a plot, speed against
error); `granpipe report` on demand; --no-report; without matplotlib the tables still shown
and the page says why; a folder that is no run refused in one line with exit 2, and so is a
damaged pipeline.json (truncated, a list, not UTF-8, a sweep that is no object, paper values
whose x and y differ in length), by granpipe report and by the script."""
import html
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from html.parser import HTMLParser

exe, pipeline, python = sys.argv[1], sys.argv[2], sys.argv[3]
toy = ["--set", "source.params.N=64", "--set", "source.params.side=6", "--set",
       "source.params.taps=3", "--quiet"]
failures = []


class Page(HTMLParser):
    """The page's figures (id -> the text inside its SVG and the number of line paths),
    table cells, and notes."""

    def __init__(self, path):
        super().__init__()
        self.figures, self.cells, self.notes = {}, [], []
        self._figure, self._where = None, None
        with open(path) as f:
            self.feed(f.read())

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "figure":
            self._figure = attrs["id"]
            self.figures[self._figure] = {"text": [], "paths": 0}
        elif tag == "path" and self._figure:
            self.figures[self._figure]["paths"] += 1
        elif tag == "td":
            self._where = "cell"
        elif tag == "p" and attrs.get("class") == "note":
            self._where = "note"

    def handle_endtag(self, tag):
        if tag == "figure":
            self._figure = None
        if tag in ("td", "p"):
            self._where = None

    def handle_data(self, data):
        if self._figure:
            self.figures[self._figure]["text"].append(data)
        elif self._where == "cell":
            self.cells.append(data)
        elif self._where == "note":
            self.notes.append(data)


def holds(path, group):
    """Whether the HDF5 file a run writes holds `group` yet."""
    import h5py
    try:
        with h5py.File(path, "r", swmr=True, locking=False) as f:
            return group in f
    except (OSError, KeyError, RuntimeError):  # not there yet, or caught mid-write: again
        return False


def check(condition, message):
    if not condition:
        failures.append(message)


with tempfile.TemporaryDirectory() as work:
    single = os.path.join(work, "single")
    subprocess.run([exe, pipeline, *toy, "--set", 'sweep.parameters={"source.params.epsilon": '
                    '[0.05]}', "--set", "output.save_frames=true", "--out", single], check=True)
    page = Page(os.path.join(single, "report.html"))
    # Written under a temporary name of its own, then readable as the run's other files are.
    mask = os.umask(0)
    os.umask(mask)
    check(os.stat(os.path.join(single, "report.html")).st_mode & 0o777 == 0o666 & ~mask,
          "the report's permissions are not the umask's")
    check(not [n for n in os.listdir(single) if n.endswith(".tmp")], "a temporary was left")
    with open(os.path.join(single, "pipeline.json")) as f:
        seed = json.load(f)["seed"]
    check(str(seed) in page.cells and "git_commit" in page.cells, f"provenance: {page.cells[:14]}")
    for stage in ("source spheres3d_tap", "analyzer packing", "analyzer compaction",
                  "frames file"):
        check(f"seconds in {stage}" in page.cells, f"provenance: no time of {stage}")
    for plot, label in (("plot-per_frame", "tap"),):
        figure = page.figures.get(plot)
        check(figure is not None, f"{plot} missing: {sorted(page.figures)}")
        if figure:
            check(any(label in t for t in figure["text"]), f"{plot}: no axis {label}")
            check(figure["paths"] > 4, f"{plot}: {figure['paths']} paths: nothing drawn")
    check("X_inf" in page.cells, "the Eq. (3) fit's parameters are not shown")
    # The saved frames' last one drawn: a side view, a section per sphere in the slab.
    picture = page.figures.get("configuration", {"text": [], "paths": 0})
    check(any("side view" in t for t in picture["text"]) and picture["paths"] > 4,
          f"configuration: {picture['paths']} paths, {picture['text'][:6]}")

    sweep = os.path.join(work, "sweep")
    subprocess.run([exe, pipeline, *toy, "--no-report", "--out", sweep], check=True)
    check(not os.path.exists(os.path.join(sweep, "report.html")), "--no-report wrote a report")
    r = subprocess.run([exe, "report", sweep], capture_output=True, text=True)
    check(r.returncode == 0, f"granpipe report: {r.returncode} {r.stderr}")
    page = Page(os.path.join(sweep, "report.html"))
    legend = " ".join(page.figures.get("plot-per_frame", {"text": []})["text"])
    for eps in ("0.005", "0.05", "0.15"):
        check(f"epsilon = {eps}" in legend, f"sweep: no line of epsilon {eps} in {legend[:200]}")

    # The pipeline's "report": phi_c against epsilon, the paper's values over it (and a note
    # for values whose plot the run did not make), speed against error over epsilon.
    declared = os.path.join(work, "declared")
    report = {"sweep_plots": [{"name": "phi", "x": "source.params.epsilon",
                               "y": ["compaction.phi_c_ss"], "xlabel": "the dilation"}],
              "paper": [{"plot": "sweep/phi", "label": "values of a paper", "x": [0.05, 0.15],
                         "y": [0.59, 0.6], "y_err": [0.01, 0.01]},
                        {"plot": "compaction/no_such_plot", "label": "lost", "x": [1], "y": [1]}],
              "speed_vs_error": {"knob": "source.params.epsilon", "time": "source.seconds",
                                 "quantities": ["packing.phi"]}}
    subprocess.run([exe, pipeline, *toy, "--set", "report=" + json.dumps(report), "--out",
                    declared], check=True)
    page = Page(os.path.join(declared, "report.html"))
    phi = " ".join(page.figures.get("sweep-phi", {"text": []})["text"])
    check("the dilation" in phi and "values of a paper" in phi, f"sweep plot phi: {phi[:300]}")
    check(any("compaction/no_such_plot: this run has no such plot" in n for n in page.notes),
          f"paper values without their plot: not said ({page.notes})")
    with open(os.path.join(declared, "report.html")) as f:
        speed_table = "<th>packing.phi_deviation</th>" in f.read()
    check("speed-vs-error" in page.figures and speed_table,
          f"speed against error: {sorted(page.figures)}, table {speed_table}")

    # A long sweep draws a bounded number of its points (the page's size), and says so.
    long_sweep = os.path.join(work, "long_sweep")
    epsilons = ", ".join(f"{0.01 * (k + 1):g}" for k in range(30))
    subprocess.run([exe, pipeline, *toy, "--no-report", "--set",
                    f'sweep.parameters={{"source.params.epsilon": [{epsilons}]}}', "--out",
                    long_sweep], check=True)
    subprocess.run([exe, "report", long_sweep], check=True)
    with open(os.path.join(long_sweep, "report.html")) as f:
        text = f.read()
    check("compaction, 24 of 30 points" in text, "a long sweep's plots: no bound said")
    # Their lines named in a legend beside the plot (past 12 lines there was none).
    check("epsilon = 0.3" in text, "a long sweep's plots: no legend naming the points")
    # The legend inside the picture: its canvas wider than the plot's 6.4 in (460.8 pt).
    widths = [float(w) for w in re.findall(r'viewBox="0 0 ([0-9.]+) ', text)]
    check(widths and max(widths) > 470, f"a long sweep's legend cut off: widths {widths[:6]}")
    # Each of its lines in a colour of its own (the default cycle repeats every 10).
    colours = set(re.findall(r"stroke: ?(#[0-9a-f]{6})", text))
    check(len(colours) >= 24, f"a long sweep's plots: {len(colours)} colours for 24 lines")

    # No matplotlib: a module of that name that fails to import stands for its absence.
    hidden = os.path.join(work, "hidden")
    os.makedirs(os.path.join(hidden, "matplotlib"))
    with open(os.path.join(hidden, "matplotlib", "__init__.py"), "w") as f:
        f.write("raise ImportError('hidden for the test')\n")
    script = os.path.join(os.path.dirname(os.path.dirname(exe)), "share", "granpipe", "report.py")
    env = dict(os.environ, PYTHONPATH=hidden)
    subprocess.run([python, script, single], check=True, env=env)
    page = Page(os.path.join(single, "report.html"))
    check(any("matplotlib is not installed" in n for n in page.notes), f"notes: {page.notes}")
    check(not page.figures and "X_inf" in page.cells, "without matplotlib: tables missing")

    # The warnings of run.log (undefined results) are on the page too.
    with open(os.path.join(single, "run.log")) as f:
        said = [line[len("warning: "):].strip() for line in f if line.startswith("warning: ")]
    with open(os.path.join(single, "report.html")) as f:
        text = f.read()
    check(bool(said) and all(html.escape(s)[:60] in text for s in said),
          f"run.log's warnings not on the page: {said[:3]}")
    # A fit says its status (why it is undefined), recorded beside it by its producer.
    fit_block = text[text.find("<h4>fit eq3"):][:2000]
    check("<p>status " in fit_block, f"the Eq. (3) fit's status is not shown: {fit_block[:300]}")

    # A sweep stopped with SIGTERM: the page says so and why, shows each point's results so
    # far (its point groups were headings over nothing), and no wall time of 0.
    stopped = os.path.join(work, "stopped")
    endless = [a if a != "source.params.taps=3" else "source.params.taps=100000" for a in toy]
    run = subprocess.Popen([exe, pipeline, *endless, "--no-report", "--out", stopped])
    partial = os.path.join(stopped, "results.partial.h5")
    for _ in range(1200):  # until point 0 has results to show
        if run.poll() is not None or holds(partial, "point_000/compaction"):
            break
        time.sleep(0.05)
    run.send_signal(signal.SIGTERM)
    check(run.wait() in (-signal.SIGTERM, 128 + signal.SIGTERM),
          f"the endless sweep ended by itself: {run.returncode}")
    subprocess.run([exe, "report", stopped], check=True)
    page = Page(os.path.join(stopped, "report.html"))
    check(any("this run was interrupted by SIGTERM" in n for n in page.notes),
          f"a stopped run's state: {page.notes}")
    check("not measured (the run has not finished)" in page.cells and "0.0" not in page.cells,
          f"a stopped run's wall time: {page.cells[:16]}")
    with open(os.path.join(stopped, "report.html")) as f:
        check('id="point_000/compaction"' in f.read(), "a stopped sweep's points: no results")

    # The run completing while its page of the results so far is drawn: that page landed
    # after the run had removed it, stale. Drawn again from the complete results instead.
    racing = os.path.join(work, "racing")
    shutil.copytree(stopped, racing)
    os.remove(os.path.join(racing, "report.html"))
    share = os.path.join(os.path.dirname(os.path.dirname(exe)), "share", "granpipe")
    completes = ("import shutil, sys; sys.path.insert(0, sys.argv[1]); import report\n"
                 "draw = report.report_body\n"
                 "def completing(*args):\n"
                 "    page = draw(*args)\n"
                 "    shutil.copy(sys.argv[2] + '/results.partial.h5', sys.argv[2] + '/results.h5')\n"
                 "    return page\n"
                 "report.report_body = completing\n"
                 "report.main(sys.argv[2])\n")
    subprocess.run([python, "-c", completes, share, racing], check=True)
    page = Page(os.path.join(racing, "report.html"))
    check(not any("the results so far" in n for n in page.notes),
          f"a page drawn as the run completed: {page.notes}")
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(exe)), "share", "granpipe"))
    from report_parts import number
    check(number(1412032.0) == "1412032" and number(0.5) == "0.5" and number(2.5e20) == "2.5e+20",
          f"numbers: {number(1412032.0)} {number(0.5)} {number(2.5e20)}")
    import numpy as np  # numpy's float32 read 1.41203e+06 and its NaN "nan"
    check(number(np.float32(1412032)) == "1412032" and number(np.float32("nan")) == "undefined",
          f"float32: {number(np.float32(1412032))} {number(np.float32('nan'))}")

    # A report.html that granpipe did not write is the user's: refused, left as it was.
    with open(os.path.join(sweep, "report.html"), "w") as f:
        f.write("my notes")
    r = subprocess.run([exe, "report", sweep], capture_output=True, text=True)
    with open(os.path.join(sweep, "report.html")) as f:
        kept = f.read()
    check(r.returncode == 2 and "expected a report granpipe wrote, found another file" in r.stderr
          and kept == "my notes", f"a user's report.html: {r.returncode} {r.stderr!r} {kept!r}")

    # A directory in its place was called "another file".
    os.remove(os.path.join(sweep, "report.html"))
    os.makedirs(os.path.join(sweep, "report.html"))
    r = subprocess.run([exe, "report", sweep], capture_output=True, text=True)
    check(r.returncode == 2 and r.stderr.startswith("granpipe: ") and
          "expected a report granpipe wrote, found a directory" in r.stderr
          and os.path.isdir(os.path.join(sweep, "report.html")),
          f"a directory report.html: {r.returncode} {r.stderr!r}")
    os.rmdir(os.path.join(sweep, "report.html"))

    # A symlink named report.html is the user's: it was replaced by a file, listed as the run's.
    os.symlink(os.path.join(single, "report.html"), os.path.join(sweep, "report.html"))
    r = subprocess.run([exe, "report", sweep], capture_output=True, text=True)
    check(r.returncode == 2 and os.path.islink(os.path.join(sweep, "report.html")) and
          "expected a report granpipe wrote, found a symbolic link" in r.stderr,
          f"a symlink report.html: {r.returncode} {r.stderr!r}")
    os.remove(os.path.join(sweep, "report.html"))

    empty = os.path.join(work, "empty")
    os.makedirs(empty)
    r = subprocess.run([exe, "report", empty], capture_output=True, text=True)
    # One line: the script's refusal, not followed by another blaming the script.
    check(r.returncode == 2 and r.stderr.count("\n") == 1 and
          "pipeline.json: expected the pipeline of a granpipe run, found none" in r.stderr,
          f"not a run: {r.returncode} {r.stderr!r}")

    # A damaged pipeline.json: one line naming it and what was expected, exit 2, no traceback.
    damaged = os.path.join(work, "damaged")
    os.makedirs(damaged)
    path = os.path.join(damaged, "pipeline.json")
    paper = {"report": {"paper": [{"plot": "p/q", "label": "L", "x": [1, 2, 3], "y": [1, 2]}]}}
    cases = {
        b'{"name": "x", "sweep": {': "expected the pipeline of a granpipe run, found malformed "
                                     "JSON: Expecting property name enclosed in double quotes: "
                                     "line 1 column 25 (char 24)",
        b"[1, 2]": "expected the pipeline of a granpipe run (a JSON object), found a JSON list",
        b"\xff\xfe\x00": "expected the pipeline of a granpipe run (UTF-8 JSON), found byte 0xff "
                         "at offset 0, which is not UTF-8",
        b'{"sweep": "grid"}': 'sweep: expected an object, found "grid"',
        json.dumps(paper).encode(): "report.paper[0]: expected x, y of one length, found lengths 3, 2",
    }
    script = os.path.join(os.path.dirname(os.path.dirname(exe)), "share", "granpipe", "report.py")
    for content, message in cases.items():
        with open(path, "wb") as f:
            f.write(content)
        for command in ([exe, "report", damaged], [python, script, damaged]):
            r = subprocess.run(command, capture_output=True, text=True)
            check(r.returncode == 2 and r.stderr == f"granpipe: {path}: {message}\n",
                  f"{content!r} by {command[1]}: {r.returncode} {r.stderr!r}")
if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print("report.html: provenance, declared plots with their axes, fits; sweeps; on demand; "
      "without matplotlib")
