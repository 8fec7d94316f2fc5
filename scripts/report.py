#!/usr/bin/env python3
"""report.html of a granpipe run: one self-contained page in the run directory with the
pipeline as run, its provenance, every result (scalars, fits, histograms, tables) and every
plot a plugin declared (drawn with matplotlib, inlined as SVG).

usage: report.py RUN_DIR

The run's results.h5 is read (results.partial.h5 of a run still going or stopped, said so
on the page); without h5py the page lists the CSV files instead, and without matplotlib it
says so and shows the tables. The page is written under a temporary name and renamed, so that
a reader never sees half a page and nothing else in RUN_DIR is touched."""
import html
import io
import math
import os
import sys

TABLE_ROWS_SHOWN = 12  # a long table is cut on the page; its CSV file has every row
SWEEP_ROWS_SHOWN = 100  # the sweep's summary: a row per point
MARKED_POINTS = 60  # a line of more points is drawn without a marker at each (page size)
MAX_LEGEND_LINES = 12
MAX_DRAWN_PARTICLES = 20000  # a configuration picture of more would be pages of SVG
MAX_SWEEP_LINES = 24  # a sweep's plots draw at most this many points (the page's size)  # more lines than this make a legend that hides the plot


def refuse(message):
    print(message, file=sys.stderr)
    sys.exit(2)


def text(value):
    """An HDF5 attribute as a str (h5py gives bytes or numpy strings)."""
    if isinstance(value, bytes):
        return value.decode()
    return str(value)


def texts(value):
    return [text(v) for v in value]


def number(x):
    if isinstance(x, float) and math.isnan(x):
        return "undefined"
    return f"{x:.6g}"


def with_error(value, error):
    return number(value) if math.isnan(error) else f"{number(value)} ± {error:.2g}"


def csv_name(producer, name):
    """The CSV file the run wrote beside results.h5 for a table of `producer`."""
    return producer.replace("/", ".") + f".{name}.csv"


def html_table(header, rows):
    """A table; header None: rows only."""
    head = "".join(f"<th>{html.escape(h)}</th>" for h in header or [])
    body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in row) + "</tr>"
                   for row in rows)
    return f"<table>{f'<tr>{head}</tr>' if head else ''}{body}</table>"


def scalars_section(group):
    rows = []
    for name, item in group.items():
        if text(item.attrs.get("kind", "")) != "scalar":
            continue
        value = float(item[()])
        rows.append([name, with_error(value, float(item.attrs["uncertainty"])),
                     text(item.attrs["unit"]), text(item.attrs["doc"])])
    return html_table(["scalar", "value", "unit", "what"], rows) if rows else ""


def fit_section(name, group):
    values, errors = group["values"][()], group["errors"][()]
    rows = [[p, with_error(float(v), float(e))]
            for p, v, e in zip(texts(group.attrs["names"]), values, errors)]
    chi2, dof = float(group.attrs["chi2"]), int(group.attrs["dof"])
    return (f"<h4>fit {html.escape(name)}</h4><p><code>{html.escape(text(group.attrs['model']))}"
            f"</code> (χ² = {number(chi2)}, {dof} degrees of freedom)</p>"
            + html_table(["parameter", "value"], rows))


def table_section(producer, name, group, rows_shown=TABLE_ROWS_SHOWN):
    columns, units = texts(group.attrs["columns"]), texts(group.attrs["units"])
    data = [group[c][()] for c in columns]
    n = len(data[0]) if data else 0
    header = [f"{c} ({u})" if u else c for c, u in zip(columns, units)]
    rows = [[number(float(col[r])) for col in data] for r in range(min(n, rows_shown))]
    more = (f" — the first {rows_shown} of {n} rows; every row in "
            f"<a href=\"{csv_name(producer, name)}\">{csv_name(producer, name)}</a>"
            if n > rows_shown else f" — {n} rows")
    return (f"<h4>table {html.escape(name)}</h4><p>{html.escape(text(group.attrs['doc']))}{more}"
            f"</p>" + html_table(header, rows))


def histogram_section(name, group):
    edges, values, errors = group["edges"][()], group["values"][()], group["errors"][()]
    rows = [[f"{number(float(edges[k]))} – {number(float(edges[k + 1]))}",
             with_error(float(values[k]), float(errors[k]))] for k in range(len(values))]
    return (f"<h4>histogram {html.escape(name)}</h4><p>{html.escape(text(group.attrs['doc']))}</p>"
            + html_table([text(group.attrs["xlabel"]), "value"], rows[:TABLE_ROWS_SHOWN]))


def axis_label(label, unit):
    """The plugin's label, with the column's unit when the label does not give one."""
    return f"{label} ({unit})" if unit and unit not in label else label


def drawable(x, y, e, logx, logy):
    """The points a plot can show: finite, and positive on a log axis."""
    import numpy as np
    keep = np.isfinite(x) & np.isfinite(y)
    if logx:
        keep &= x > 0
    if logy:
        keep &= y > 0
    return x[keep], y[keep], None if e is None else e[keep]


def plot_svg(plt, declared, tables):
    """The declared plot as an inline SVG element, or None when no point can be drawn: one
    line per y column of each (label, table) of `tables` (one table in a single run, one per
    sweep point in a sweep)."""
    x_name = text(declared.attrs["x"])
    logx, logy = bool(int(declared.attrs["logx"])), bool(int(declared.attrs["logy"]))
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    drawn = 0
    for label, table in tables:
        for y_name in texts(declared.attrs["y"]):
            error = f"{y_name}_err"
            x, y, e = drawable(table[x_name][()], table[y_name][()],
                               table[error][()] if error in table else None, logx, logy)
            drawn += len(x)
            line_label = " ".join(part for part in (label, y_name) if part)
            marker = "." if len(x) <= MARKED_POINTS else None
            if e is not None and marker:
                ax.errorbar(x, y, yerr=e, label=line_label, marker=marker, capsize=2)
                continue
            (line,) = ax.plot(x, y, label=line_label, marker=marker)
            if e is not None:  # a band: one path, where error bars would be one per point
                ax.fill_between(x, y - e, y + e, color=line.get_color(), alpha=0.25, lw=0)
    if drawn == 0:
        plt.close(fig)
        return None
    first = tables[0][1]
    unit_of = dict(zip(texts(first.attrs["columns"]), texts(first.attrs["units"])))
    ax.set_xlabel(axis_label(text(declared.attrs["xlabel"]), unit_of.get(x_name, "")))
    ax.set_ylabel(text(declared.attrs["ylabel"]))
    ax.set_title(text(declared.attrs["title"]))
    if logx:
        ax.set_xscale("log")
    if logy:
        ax.set_yscale("log")
    if len(ax.get_lines()) <= MAX_LEGEND_LINES:
        ax.legend(fontsize="small")
    fig.tight_layout()
    out = io.StringIO()
    fig.savefig(out, format="svg", metadata={"Date": None})  # the same run, the same page
    plt.close(fig)
    svg = out.getvalue()
    return svg[svg.index("<svg"):]  # inline: without the XML prolog


def plots_section(plt, groups):
    """Every plot the producer declared; `groups` is [(label, its results group)]: the run's
    group, or one per sweep point, drawn together."""
    declared_in = groups[0][1]
    if "_plots" not in declared_in:
        return ""
    if plt is None:
        return "<p class=note>plots not drawn: matplotlib is not installed</p>"
    parts = []
    for name, declared in declared_in["_plots"].items():
        table = text(declared.attrs["table"])
        tables = [(label, g[table]) for label, g in groups if table in g]
        if not tables:
            parts.append(f"<p class=note>plot {html.escape(name)}: its table {table} is "
                         "not in the results</p>")
            continue
        svg = plot_svg(plt, declared, tables)
        if svg is None:
            parts.append(f"<p class=note>plot {html.escape(name)}: no point to draw (none finite"
                         ", or none positive on its log axis)</p>")
            continue
        parts.append(f"<figure id=\"plot-{html.escape(name)}\">{svg}"
                     f"<figcaption>{html.escape(name)}</figcaption></figure>")
    return "".join(parts)


def producer_section(plt, path, group):
    parts = [f"<h3 id=\"{html.escape(path)}\">{html.escape(path)}</h3>",
             plots_section(plt, [("", group)]), scalars_section(group)]
    for name, item in group.items():
        kind = text(item.attrs.get("kind", ""))
        if kind == "fit":
            parts.append(fit_section(name, item))
        elif kind == "table":
            parts.append(table_section(path, name, item))
        elif kind == "histogram":
            parts.append(histogram_section(name, item))
    return "".join(parts)


def last_frame(path):
    """(positions, radii, particle columns {name: values}, contacts (i, j, |F_n|) or None,
    step) of the last frame of a granpipe frames file."""
    import h5py
    import numpy as np
    with h5py.File(path, "r", swmr=True) as f:
        particles = f["particles/all"]
        t = len(particles["position/step"]) - 1
        if t < 0:
            return None
        columns = {name: particles[name]["value"][t] for name in particles
                   if name not in ("position", "radius", "box") and "value" in particles[name]}
        contacts = None
        if "granpipe/contacts" in f and "normal_force" in f["granpipe/contacts"]:
            c = f["granpipe/contacts"]
            rows = slice(int(c["offset"][t]), int(c["offset"][t] + c["count"][t]))
            force = np.linalg.norm(np.atleast_2d(c["normal_force"][rows]), axis=-1)
            contacts = (c["i"][rows], c["j"][rows], force)
        return (particles["position/value"][t], particles["radius/value"][t], columns, contacts,
                int(particles["position/step"][t]))


def configuration_svg(plt, frame):
    """The last frame drawn: 2D disks (an arch's disks coloured by arch), or a 3D packing's
    side view (x, z) of the slab of centres within a mean radius of the middle y, each sphere
    as its section by the mid-plane; particle-particle contacts in view as lines of width in
    proportion to |F_n| (the BNP paper's Fig. 11)."""
    import numpy as np
    from matplotlib.collections import LineCollection, PatchCollection
    from matplotlib.patches import Circle
    x, r, columns, contacts, step = frame
    if x.shape[1] == 3:
        middle = 0.5 * (x[:, 1].min() + x[:, 1].max())
        depth = x[:, 1] - middle
        shown = np.abs(depth) < r.mean()
        section = np.sqrt(np.maximum(r**2 - depth**2, 0.0))
        xy, size, title = x[:, [0, 2]], section, f"side view of the slab |y - {middle:.3g}| < R̄"
    else:
        shown, xy, size, title = np.ones(len(r), bool), x, r, "the packing"
    if shown.sum() > MAX_DRAWN_PARTICLES:
        return None
    arch = columns.get("arch")
    colours = ["#c8c8c8" if arch is None or a < 0 else plt.cm.tab20(int(a) % 20)
               for a in (arch if arch is not None else np.full(len(r), -1))]
    index = np.flatnonzero(shown)
    extent = np.ptp(xy[index], axis=0) + 2.0 * r.max()
    tall = float(np.clip(extent[1] / extent[0], 0.5, 2.0))  # a tall bed drawn tall, within reason
    fig, ax = plt.subplots(figsize=(6.4, 6.4 * tall))
    ax.add_collection(PatchCollection([Circle(xy[k], size[k]) for k in index],
                                      facecolors=[colours[k] for k in index], edgecolors="k",
                                      linewidths=0.2))
    if contacts is not None:
        i, j, force = contacts
        keep = (j >= 0) & (force > 0)
        keep[keep] &= shown[i[keep]] & shown[j[keep]]
        if keep.any():
            segments = np.stack([xy[i[keep]], xy[j[keep]]], axis=1)
            ax.add_collection(LineCollection(segments, colors="#b22",
                                             linewidths=3.0 * force[keep] / force[keep].max()))
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_title(f"{title}, step {step}")
    ax.set_xlabel("x")
    ax.set_ylabel("z" if x.shape[1] == 3 else "y")
    fig.tight_layout()
    out = io.StringIO()
    fig.savefig(out, format="svg", metadata={"Date": None})
    plt.close(fig)
    svg = out.getvalue()
    return svg[svg.index("<svg"):]


def configuration_section(plt, run):
    """A picture of the last saved frame, when the run saved frames (a sweep: its first point)."""
    for name in ("frames.h5", "frames.partial.h5", "point_000/frames.h5"):
        path = os.path.join(run, name)
        if os.path.exists(path):
            break
    else:
        return ""
    if plt is None:
        return ""
    frame = last_frame(path)
    svg = configuration_svg(plt, frame) if frame is not None else None
    if svg is None:
        return (f"<p class=note>{html.escape(name)}: no picture (no frame, or more than "
                f"{MAX_DRAWN_PARTICLES} particles in view)</p>")
    return (f"<h2>Configuration</h2><figure id=configuration>{svg}<figcaption>the last frame of "
            f"{html.escape(name)}</figcaption></figure>")


def point_labels(results):
    """{point group name: "point k: swept values"} from the sweep's summary table."""
    points = results["sweep/points"]
    columns = texts(points.attrs["columns"])
    swept = [c for c in columns[1:] if ".params." in c]  # the swept paths, then scalars
    labels = {}
    for row in range(len(points["point"][()])):
        k = int(points["point"][row])
        values = ", ".join(f"{c.split('.')[-1]} = {number(float(points[c][row]))}" for c in swept)
        labels[f"point_{k:03d}"] = f"{k}: {values}" if values else str(k)
    return labels


def sweep_section(plt, results):
    """A sweep: its summary table, and each producer's declared plots with every point drawn."""
    points = results["sweep/points"]
    parts = ["<h3 id=sweep>sweep</h3>",
             table_section("sweep", "points", points, SWEEP_ROWS_SHOWN)]
    labels = point_labels(results)
    drawn = sorted(labels)
    if len(drawn) > MAX_SWEEP_LINES:  # evenly spaced points, the first and the last among them
        step = (len(drawn) - 1) / (MAX_SWEEP_LINES - 1)
        drawn = [drawn[round(k * step)] for k in range(MAX_SWEEP_LINES)]
    which = "every point" if len(drawn) == len(labels) else f"{len(drawn)} of {len(labels)} points"
    names = sorted({sub for p in labels for sub in results[p].keys()})
    for name in names:
        groups = [(labels[p], results[p][name]) for p in drawn if name in results[p]]
        if not groups:
            continue
        parts.append(f"<h3 id=\"{html.escape(name)}\">{html.escape(name)}, {which}</h3>"
                     + plots_section(plt, groups))
    parts.append("<p>Each point's tables, fits and scalars are in its CSV files (below).</p>")
    return "".join(parts)


def provenance_section(attrs, partial):
    keys = ["pipeline_name", "granpipe_version", "git_commit", "seed", "threads", "started",
            "wall_seconds"]
    rows = [[k, text(attrs[k])] for k in keys if k in attrs]
    state = ("<p class=note>this run has not finished (or was stopped): the results so far, "
             "from results.partial.h5</p>" if partial else "")
    return "<h2>Provenance</h2>" + state + html_table(None, rows)


STYLE = """body{font-family:sans-serif;max-width:60em;margin:1em auto;padding:0 1em}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 6px;
text-align:left;font-size:90%}.note{color:#a40}pre{background:#f4f4f4;padding:.5em;
overflow-x:auto;font-size:85%}figure{margin:1em 0}svg{max-width:100%;height:auto}"""


# Marks a page as ours: a report.html without it is the user's, and is never replaced.
GENERATOR = "<meta name=generator content=\"granpipe report\">"


def page(title, body):
    return (f"<!DOCTYPE html><html lang=en><head><meta charset=utf-8><title>{html.escape(title)}"
            f"</title>{GENERATOR}<style>{STYLE}</style></head><body><h1>{html.escape(title)}</h1>{body}"
            "</body></html>\n")


def read_results(run):
    """(h5py file or None, whether it is the partial file, a note for the page)."""
    try:
        import h5py
    except ImportError:
        return None, False, "results not shown: h5py is not installed (the CSV files hold them)"
    for name, partial in (("results.h5", False), ("results.partial.h5", True)):
        path = os.path.join(run, name)
        if os.path.exists(path):
            try:
                results = h5py.File(path, "r", swmr=partial)
            except OSError as e:
                refuse(f"{path}: expected a granpipe results file, found one HDF5 cannot open: {e}")
            if "granpipe_version" not in results.attrs:
                refuse(f"{path}: expected a granpipe results file, found an HDF5 file without "
                       "granpipe's provenance")
            return results, partial, ""
    refuse(f"{run}: expected a granpipe run directory (results.h5 or results.partial.h5), "
           "found neither")


def pyplot():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        plt.rcParams["svg.fonttype"] = "none"  # labels stay text: smaller, and searchable
        return plt
    except ImportError:
        return None


def report_body(run, results, partial, note, plt):
    with open(os.path.join(run, "pipeline.json")) as f:
        pipeline = f.read()
    parts = [f"<p class=note>{html.escape(note)}</p>" if note else ""]
    if results is not None:
        parts.append(provenance_section(results.attrs, partial))
        parts.append("<h2>Results</h2>")
        if plt is None:
            parts.append("<p class=note>plots not drawn: matplotlib is not installed</p>")
        if "sweep" in results:
            parts.append(sweep_section(plt, results))
        else:
            parts += [producer_section(plt, name, g) for name, g in results.items()]
        parts.append(configuration_section(plt, run))
    csvs = sorted(f for f in os.listdir(run) if f.endswith(".csv"))
    parts.append("<h2>Files</h2><ul>" + "".join(
        f"<li><a href=\"{html.escape(f)}\">{html.escape(f)}</a></li>" for f in csvs) + "</ul>")
    parts.append(f"<h2>Pipeline as run</h2><pre>{html.escape(pipeline)}</pre>")
    return "".join(parts)


def is_our_page(path):
    try:
        with open(path, errors="replace") as f:
            return GENERATOR in f.read(4096)
    except OSError:
        return False


def main(run):
    if not os.path.isfile(os.path.join(run, "pipeline.json")):
        refuse(f"{run}/pipeline.json: expected the pipeline of a granpipe run, found none")
    results, partial, note = read_results(run)
    name = text(results.attrs["pipeline_name"]) if results is not None else os.path.basename(run)
    html_text = page(f"granpipe run {name}", report_body(run, results, partial, note, pyplot()))
    target = os.path.join(run, "report.html")
    if os.path.lexists(target) and not is_our_page(target):
        refuse(f"{target}: expected a report granpipe wrote, found another file; it is left as "
               "it is (move it away to have the report)")
    partial = f"{target}.{os.getpid()}.tmp"  # two reports of one run at once: one wins whole
    try:
        with open(partial, "w") as f:
            f.write(html_text)
        os.replace(partial, target)
    except OSError as e:  # a full disk, a folder not ours to write: the run's files stay
        if os.path.exists(partial):
            os.remove(partial)
        refuse(f"{target}: cannot write the report: {e.strerror}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        refuse("usage: report.py RUN_DIR")
    main(sys.argv[1])
