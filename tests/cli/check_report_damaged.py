"""granpipe report of a run whose results.h5 (or frames.h5, or pipeline.json) is damaged: one
line naming the file, the dataset or attribute, what was expected and what was found, exit 2,
never a traceback; the run's files left as they were. Legitimate data (NaN and inf values, an
empty table, a histogram without errors) still report with exit 0, NaN shown as "undefined".

usage: check_report_damaged.py GRANPIPE PIPELINES_DIR"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

exe, pipelines = sys.argv[1], sys.argv[2]
failures = []
ARCHES = ["source.params.N=60", "source.params.width=6", "source.params.equilibration_taps=2",
          "source.params.production_taps=2", "source.params.save_every=1",
          'sweep.parameters={"source.params.A": [1.1]}']
COMPACTION = ["source.params.N=64", "source.params.side=6", "source.params.taps=3",
              'sweep.parameters={"source.params.epsilon": [0.05]}']
LATTICE = ['report={"sweep_plots": [{"name": "phi", "x": "source.params.lattice", '
           '"y": ["packing.phi"]}]}']


def run(pipeline, settings, out):
    args = [a for s in settings for a in ("--set", s)]
    subprocess.run([exe, os.path.join(pipelines, pipeline), *args, "--quiet", "--out", out],
                   check=True)


def in_h5(name, change):
    """A damage: change(file) of the run's HDF5 file `name`."""
    def damage(run_dir):
        with h5py.File(os.path.join(run_dir, name), "a") as f:
            change(f)
    return damage


def rewrite(path, data, file="results.h5"):
    """The dataset at `path` written anew with data(its values), its attributes kept."""
    def change(f):
        old = f[path]
        values, attrs = data(old[()]), dict(old.attrs)
        del f[path]
        f.create_dataset(path, data=values).attrs.update(attrs)
    return in_h5(file, change)


def set_attr(path, name, value):
    """The attribute set to `value`, or to value(its value) when that is a function."""
    def change(f):
        attrs = f[path].attrs
        attrs[name] = value(attrs[name]) if callable(value) else value
    return in_h5("results.h5", change)


def delete(path, attr=None):
    """The object at `path` deleted, or only its attribute `attr`."""
    def change(f):
        if attr:
            del f[path].attrs[attr]
        else:
            del f[path]
    return in_h5("results.h5", change)


def add_dataset(path, data):
    return in_h5("results.h5", lambda f: f.create_dataset(path, data=data))


def moved(source, target):
    """The object at `source` moved to `target`."""
    return in_h5("results.h5", lambda f: f.move(source, target))


def group_for_dataset(path):
    def change(f):
        del f[path]
        f.create_group(path)
    return in_h5("results.h5", change)


def each(*damages):
    def damage(run_dir):
        for d in damages:
            d(run_dir)
    return damage


def edit_pipeline(change):
    def damage(run_dir):
        path = os.path.join(run_dir, "pipeline.json")
        with open(path) as f:
            pipeline = json.load(f)
        change(pipeline)
        with open(path, "w") as f:
            json.dump(pipeline, f)
    return damage


def fifo(name):
    """The file replaced by a FIFO, which h5py would wait on for ever."""
    def damage(run_dir):
        os.remove(os.path.join(run_dir, name))
        os.mkfifo(os.path.join(run_dir, name))
    return damage


def link(path, make):
    """A link at `path` (granpipe writes none): make() an h5py.SoftLink or ExternalLink."""
    def change(f):
        f[path] = make()
    return in_h5("results.h5", change)


def flip_header(path):
    """Bytes flipped at the start of the object header of `path` in results.h5."""
    def damage(run_dir):
        name = os.path.join(run_dir, "results.h5")
        with h5py.File(name, "r") as f:
            addr = h5py.h5o.get_info(f[path].id).addr
        with open(name, "r+b") as out:
            out.seek(addr)
            head = out.read(8)
            out.seek(addr)
            out.write(bytes(b ^ 0xFF for b in head))
    return damage


def last_frame(path, value):
    """particles/all/<path> of frames.h5's last frame set to `value`."""
    def change(f):
        f[f"particles/all/{path}"][-1] = value
    return in_h5("frames.h5", change)


def no_particles(f):
    """Every per-particle dataset of frames.h5 emptied to 0 particles, its frames kept."""
    for name, g in f["particles/all"].items():
        if name != "box" and "value" in g:
            old, attrs = g["value"], dict(g["value"].attrs)
            shape, dtype = (old.shape[0], 0) + old.shape[2:], old.dtype
            del g["value"]
            g.create_dataset("value", shape=shape, dtype=dtype).attrs.update(attrs)


def declared_huge(path):
    """The dataset at `path` replaced by one declaring 1e9 values and storing none (a 24 kB
    file ended in a numpy MemoryError, exit 1, under a memory limit)."""
    def change(f):
        attrs = dict(f[path].attrs)
        del f[path]
        f.create_dataset(path, shape=(10**9,), dtype="f8", chunks=(10**6,),
                         compression="gzip").attrs.update(attrs)
    return in_h5("results.h5", change)


def contacts_declared_huge(f):
    """A contact table whose last frame declares 1e9 contacts, stored nowhere (read whole, it
    ended in a numpy MemoryError under a memory limit)."""
    frames = len(f["particles/all/position/step"])
    c = f.require_group("granpipe/contacts")
    count = np.zeros(frames, dtype="i8")
    count[-1] = 10**9
    c.create_dataset("offset", data=np.zeros(frames, dtype="i8"))
    c.create_dataset("count", data=count)
    for name, shape in (("i", (10**9,)), ("j", (10**9,)), ("normal_force", (10**9, 3))):
        c.create_dataset(name, shape=shape, dtype="f8" if name == "normal_force" else "i8",
                         chunks=(10**5,) + shape[1:], compression="gzip")


def garbage(name):
    def damage(run_dir):
        with open(os.path.join(run_dir, name), "wb") as f:
            f.write(b"no HDF5 " * 64)
    return damage


# (name, base run, damage, the message after "<run>/<file>: " as a regex[, the file])
DAMAGES = [
    ("contacts declaring 1e9 rows", "arches", in_h5("frames.h5", contacts_declared_huge),
     r"/granpipe/contacts/normal_force: expected at most 1e\+08 values to read for the report, "
     r"found 3000000000", "frames.h5"),
    ("column declaring 1e9 values", "arches", declared_huge("arches/per_frame/tap"),
     r"/arches/per_frame/tap: expected at most 1e\+08 values to read for the report, found "
     r"1000000000"),
    ("short column", "arches", rewrite("arches/per_frame/tap", lambda v: v[:-1]),
     r"/arches/per_frame/tap: expected 2 values \(as many as frame\), found 1"),
    ("scalar stored as text", "arches", rewrite("arches/arches_per_particle", lambda v: "0.5"),
     r'/arches/arches_per_particle: expected numbers, found text "0\.5"'),
    ("table without columns", "arches", delete("arches/per_frame", "columns"),
     r"/arches/per_frame attribute columns: expected a list of text, found none"),
    ("table column missing", "arches", delete("arches/per_frame/tap"),
     r"/arches/per_frame/tap: expected a dataset, found none"),
    ("table of a missing column as a producer", "arches",
     each(moved("arches/per_frame", "per_frame"), delete("per_frame/tap")),
     r'/per_frame: expected a producer \(a group of results\), found a result of kind "table"'),
    ("ragged table as a producer", "arches",
     each(moved("arches/per_frame", "per_frame"), rewrite("per_frame/tap", lambda v: v[:-1])),
     r'/per_frame: expected a producer \(a group of results\), found a result of kind "table"'),
    ("units not one per column", "arches", set_attr("arches/per_frame", "units", [b""]),
     r"/arches/per_frame attribute units: expected 11 items \(a unit per column\), found 1"),
    ("histogram edges short", "arches", rewrite("arches/span_all/edges", lambda v: v[:-2]),
     r"/arches/span_all/edges: expected \d+ values \(one more than values\), found \d+"),
    ("histogram values a group", "arches", group_for_dataset("arches/span_all/values"),
     r"/arches/span_all/values: expected a dataset, found a group"),
    ("plot of no column", "arches", set_attr("packing/_plots/profile", "x", "nope"),
     r'/packing/_plots/profile attribute x: expected a column of /packing/profile, found "nope"'),
    ("plot flag text", "arches", set_attr("packing/_plots/profile", "logy", "yes"),
     r'/packing/_plots/profile attribute logy: expected an integer, found "yes"'),
    ("column of text", "arches", rewrite("arches/per_frame/tap", lambda v: v.astype("S8")),
     r"/arches/per_frame/tap: expected numbers, found text"),
    ("2-D column", "arches", rewrite("arches/per_frame/tap", lambda v: np.stack([v, v], 1)),
     r"/arches/per_frame/tap: expected 1-D data, found shape \(2, 2\)"),
    ("doc not UTF-8", "arches", set_attr("arches/per_frame", "doc", np.bytes_(b"bad \xff")),
     r"/arches/per_frame attribute doc: expected UTF-8 text, found byte 0xff at offset 4, "
     r"which is not UTF-8"),
    ("producer a dataset", "arches", add_dataset("bogus", 1.0),
     r"/bogus: expected a group, found a dataset"),
    ("stage times short", "arches", set_attr("/", "stage_seconds", lambda v: v[:-1]),
     r"/ attribute stage_seconds: expected \d+ numbers \(one per stage\), found \d+"),
    ("fit names short", "compaction", set_attr("compaction/eq3_phi_b", "names", [b"X"]),
     r"/compaction/eq3_phi_b/values: expected 1 value \(one per name in attribute names\), "
     r"found 4"),
    ("fit dof NaN", "compaction", set_attr("compaction/eq3_phi_b", "dof", np.nan),
     r"/compaction/eq3_phi_b attribute dof: expected an integer, found nan"),
    ("table as a sweep point's producer", "lattice",
     moved("point_001/packing/profile", "point_001/profile"),
     r'/point_001/profile: expected a producer \(a group of results\), found a result of kind '
     r'"table"'),
    ("sweep point missing", "lattice", delete("point_003"),
     r"/point_003: expected a group, found none"),
    ("sweep point NaN", "lattice", rewrite("sweep/points/point", lambda v: v * np.nan),
     r"/sweep/points/point: expected whole numbers >= 0, found nan"),
    ("string parameter index out of range", "lattice",
     rewrite("sweep/points/source.params.lattice", lambda v: v + 10),
     r"/sweep/points/source\.params\.lattice: expected indices 0 to 5, found 10\.0"),
    ("sweep plot y not a list", "lattice",
     edit_pipeline(lambda p: p["report"]["sweep_plots"][0].update(y="packing.phi")),
     r'report\.sweep_plots\[0\]\.y: expected a list of result columns \("packing\.phi"\), '
     r'found "packing\.phi"', "pipeline.json"),
    ("frames not HDF5", "arches", garbage("frames.h5"),
     r"expected a granpipe frames file, found one HDF5 cannot open: .*", "frames.h5"),
    ("frames radius short", "arches",
     rewrite("particles/all/radius/value", lambda v: v[:, :-1], "frames.h5"),
     r"/particles/all/radius/value: expected 60 particles \(as many as position\), found 59",
     "frames.h5"),
    ("results a FIFO", "arches", fifo("results.h5"),
     r"expected a granpipe results file, found a FIFO \(named pipe\)"),
    ("frames a FIFO", "arches", fifo("frames.h5"),
     r"expected a granpipe frames file, found a FIFO \(named pipe\)", "frames.h5"),
    ("negative uncertainty", "arches",
     rewrite("packing/profile/phi_err", lambda v: -np.abs(v) - 0.01),
     r"/packing/profile/phi_err: expected uncertainties >= 0 \(or NaN\), found -[\d.e+-]+"),
    ("dangling external link", "arches",
     link("arches/ext", lambda: h5py.ExternalLink("/nonexistent/results.h5", "/x")),
     r'/arches/ext: expected a group or a dataset, found an external link to "/x" in '
     r'"/nonexistent/results\.h5"'),
    ("soft link to itself", "arches", link("arches/loop", lambda: h5py.SoftLink("/arches/loop")),
     r'/arches/loop: expected a group or a dataset, found a soft link to "/arches/loop"'),
    ("object header flipped", "arches", flip_header("packing/profile/phi"),
     r"expected a granpipe results file, found one HDF5 cannot read: [^\n]+"),
    ("frames radius NaN", "arches", last_frame("radius/value", np.nan),
     r"/particles/all/radius/value: expected finite numbers >= 0 in frame \d+, found nan",
     "frames.h5"),
    ("frames position inf", "arches", last_frame("position/value", np.inf),
     r"/particles/all/position/value: expected finite numbers in frame \d+, found inf",
     "frames.h5"),
]

# Data a run may hold: reported with exit 0 (NaN as "undefined"), the page holding each text
# (and none of the texts of a fifth item).
PROFILE_COLUMNS = ("height", "phi", "phi_err")
MARKUP = 'x"><img src=x onerror=alert(1)>'  # no "/": one HDF5 name


def table_named(name):
    """The table arches/per_frame renamed `name`, of 20 rows (the page links a table longer
    than it shows to its CSV file, by name)."""
    def change(f):
        table = f["arches/per_frame"]
        for c in table.attrs["columns"]:
            old = table[c]
            values, attrs = np.resize(old[()], 20), dict(old.attrs)
            del table[c]
            table.create_dataset(c, data=values).attrs.update(attrs)
        f.move("arches/per_frame", f"arches/{name}")
    return in_h5("results.h5", change)


def still_running(run_dir):
    """The run as it is while going: results.partial.h5 marked incomplete, a row of its
    streamed table written to one column and not yet to the others (a report of a running
    run called that file damaged, 3 times in 10)."""
    partial = os.path.join(run_dir, "results.partial.h5")
    os.rename(os.path.join(run_dir, "results.h5"), partial)
    with h5py.File(partial, "a") as f:
        f.attrs["complete"] = 0
        old = f["arches/per_frame/tap"]
        values, attrs = np.append(old[()], 99.0), dict(old.attrs)
        del f["arches/per_frame/tap"]
        f.create_dataset("arches/per_frame/tap", data=values).attrs.update(attrs)


LEGITIMATE = [
    ("a row written to one column of a running run", "arches", still_running,
     ["<h4>table per_frame</h4>", "results.partial.h5"], ["<td>99</td>"]),
    ("NaN and inf in a column", "arches",
     rewrite("packing/profile/phi", lambda v: np.resize([np.nan, np.inf], len(v))),
     ["<td>undefined</td>", "<td>inf</td>"]),
    ("empty table", "arches",
     each(*(rewrite(f"packing/profile/{c}", lambda v: v[:0]) for c in PROFILE_COLUMNS)),
     [" — 0 rows", "plot profile: no point to draw"]),
    ("histogram without errors", "arches", delete("arches/span_all/errors"),
     ["<h4>histogram span_all</h4>"]),
    ("title of invalid mathtext", "arches",
     each(set_attr("packing/_plots/profile", "title", "cost $\\foo$"),
          set_attr("packing/_plots/profile", "ylabel", "$x^$")),
     ["cost $\\foo$", "$x^$"]),
    ("table name of markup", "arches", table_named(MARKUP),
     ['href="arches.x&quot;&gt;&lt;img src=x onerror=alert(1)&gt;.csv"'], ["<img"]),
    ("frames of no particle", "arches", in_h5("frames.h5", no_particles),
     ["frames.h5: no picture (its last frame has no particle)"]),
]


def damaged_copy(work, base, name, damage):
    run_dir = os.path.join(work, re.sub(r"\W+", "_", name))
    shutil.copytree(os.path.join(work, base), run_dir)
    damage(run_dir)
    return run_dir


def report(run_dir):
    """granpipe report of the run; one that hangs (a FIFO read) is stopped, exit None."""
    try:
        return subprocess.run([exe, "report", run_dir], capture_output=True, text=True,
                              timeout=120)
    except subprocess.TimeoutExpired as e:
        return subprocess.CompletedProcess(e.cmd, None, "", "timed out")


def files(run_dir):
    """{path: bytes} of every file of the run (a FIFO: its mode, never read)."""
    out = {}
    for top, _, names in os.walk(run_dir):
        for n in names:
            path = os.path.join(top, n)
            if not os.path.isfile(path):
                out[os.path.relpath(path, run_dir)] = os.lstat(path).st_mode
                continue
            with open(path, "rb") as f:
                out[os.path.relpath(path, run_dir)] = f.read()
    return out


with tempfile.TemporaryDirectory() as work:
    run("tap2d_arches.json", ARCHES, os.path.join(work, "arches"))
    run("tap3d_compaction.json", COMPACTION, os.path.join(work, "compaction"))
    run("lattice_packing.json", LATTICE, os.path.join(work, "lattice"))
    for base in ("arches", "compaction", "lattice"):
        r = report(os.path.join(work, base))
        if r.returncode != 0 or r.stderr:
            failures.append(f"the good {base} run: exit {r.returncode}, {r.stderr!r}")

    for name, base, damage, message, *file in DAMAGES:
        run_dir = damaged_copy(work, base, name, damage)
        before = files(run_dir)
        r = report(run_dir)
        path = re.escape(os.path.join(run_dir, file[0] if file else "results.h5"))
        if r.returncode != 2 or not re.fullmatch(f"granpipe: {path}: {message}\n", r.stderr):
            failures.append(f"{name}: exit {r.returncode}, {r.stderr!r}")
        if files(run_dir) != before:  # the refusal writes nothing, its report.html stays
            failures.append(f"{name}: the run's files changed")

    for name, base, damage, expected, *absent in LEGITIMATE:
        run_dir = damaged_copy(work, base, name, damage)
        os.remove(os.path.join(run_dir, "report.html"))  # the page read is the one written now
        r = report(run_dir)
        page_path = os.path.join(run_dir, "report.html")
        page = open(page_path).read() if os.path.exists(page_path) else ""
        missing = [e for e in expected if e not in page]
        present = [a for a in (absent[0] if absent else []) if a in page]
        if r.returncode != 0 or r.stderr or missing or present:
            failures.append(f"{name}: exit {r.returncode}, {r.stderr!r}, "
                            f"not on the page: {missing}, on the page: {present}")

if failures:
    print("FAIL", *failures, sep="\n")
    sys.exit(1)
print(f"granpipe report: {len(DAMAGES)} damaged runs refused in one line with exit 2, "
      f"{len(LEGITIMATE)} runs of legitimate data reported")
