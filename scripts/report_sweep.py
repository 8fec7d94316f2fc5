"""report.html of a sweep: the summary table, each producer's declared plots with the points
drawn together, the plots of a result against the swept parameter the pipeline declares
("report": {"sweep_plots": [...]}), and run time against error ("speed_vs_error")."""
import html
import json

from report_h5 import damaged, indices, member, producer, read_table
from report_parts import (colour_lines, drawable, html_table, inline_svg, number, plain,
                          table_section, uncertainties)
from report_plots import plots_section
from speed_error import deviation_table, other_swept, pooled, value_namer

SWEEP_ROWS_SHOWN = 100  # the sweep's summary: a row per point
MAX_SWEEP_LINES = 24  # a sweep's plots draw at most this many points (the page's size)


# The keys of a sweep plot and of speed_vs_error: (type, what is expected, required); granpipe
# checks them when it runs the pipeline (core/src/report_spec.cpp), but pipeline.json may have
# been edited since, and the page is drawn from it.
TEXT = (str, "a string", False)
FLAG = (bool, "true or false", False)
SWEPT = (str, "a swept parameter", True)
COLUMNS = (list, 'a list of result columns ("packing.phi")', True)
SWEEP_PLOT_KEYS = {"name": (str, "a name for the plot", True), "x": SWEPT, "y": COLUMNS,
                   "xlabel": TEXT, "ylabel": TEXT, "title": TEXT, "logx": FLAG, "logy": FLAG}
SPEED_VS_ERROR_KEYS = {"knob": SWEPT, "time": (str, 'a result column ("source.seconds")', True),
                       "quantities": COLUMNS, "pool": (str, "a swept parameter", False)}


def spec_problem(where, spec, keys):
    """What is wrong with the object `spec` at `where` ("where: expected ..., found ..."), or
    "": each of `keys` of its type (a list: of strings), the required ones there."""
    if not isinstance(spec, dict):
        return f"{where}: expected an object, found {json.dumps(spec)}"
    for key, (kind, expected, required) in keys.items():
        if key not in spec:
            if required:
                return f"{where}.{key}: expected {expected}, found none"
            continue
        value = spec[key]
        if not isinstance(value, kind) or (kind is list and not all(isinstance(v, str)
                                                                     for v in value)):
            return f"{where}.{key}: expected {expected}, found {json.dumps(value)}"
    return ""


def report_problem(report):
    """What is wrong with the pipeline's "report" sweep plots and speed_vs_error, or ""."""
    plots = report.get("sweep_plots", [])
    if not isinstance(plots, list):
        return f"report.sweep_plots: expected a list of sweep plots, found {json.dumps(plots)}"
    problems = [spec_problem(f"report.sweep_plots[{k}]", spec, SWEEP_PLOT_KEYS)
                for k, spec in enumerate(plots)]
    if "speed_vs_error" in report:
        problems.append(spec_problem("report.speed_vs_error", report["speed_vs_error"],
                                     SPEED_VS_ERROR_KEYS))
    return next((p for p in problems if p), "")


def point_labels(results, points, pipeline):
    """{point group name: "point k: swept values"} from the sweep's summary table, whose
    points each have their group; a string parameter by its string (it read "lattice = 3")."""
    columns, _, data = read_table(points)
    if "point" not in data:
        raise damaged(points, 'a column "point"', "none", "columns")
    indices(points, "point", data["point"])
    swept = [c for c in columns[1:] if ".params." in c]  # the swept paths, then scalars
    name_of = value_namer(pipeline)
    labels = {}
    for row, k in enumerate(data["point"].astype(int)):
        member(results, f"point_{k:03d}", "group")
        values = ", ".join(f"{c.split('.')[-1]} = {name_of(c, data[c][row])}" for c in swept)
        labels[f"point_{k:03d}"] = f"{k}: {values}" if values else str(k)
    return labels


def sweep_section(plt, results, pipeline, paper):
    """A sweep: its summary table, and each producer's declared plots with every point drawn."""
    points = member(results, "sweep/points", "group")
    parts = ["<h3 id=sweep>sweep</h3>",
             table_section("sweep", "points", points, SWEEP_ROWS_SHOWN),
             declared_sweep_section(plt, results, pipeline, paper)]
    labels = point_labels(results, points, pipeline)
    drawn = sorted(labels)
    if len(drawn) > MAX_SWEEP_LINES:  # evenly spaced points, the first and the last among them
        step = (len(drawn) - 1) / (MAX_SWEEP_LINES - 1)
        drawn = [drawn[round(k * step)] for k in range(MAX_SWEEP_LINES)]
    which = "every point" if len(drawn) == len(labels) else f"{len(drawn)} of {len(labels)} points"
    names = sorted({sub for p in labels for sub in results[p].keys()})
    for name in names:
        groups = [(labels[p], producer(results[p], name)) for p in drawn
                  if name in results[p]]
        if not groups:
            continue
        parts.append(f"<h3 id=\"{html.escape(name)}\">{html.escape(name)}, {which}</h3>"
                     + plots_section(plt, groups, name, paper))
    parts.append("<p>Each point's tables, fits and scalars are in its CSV files (below).</p>")
    return "".join(parts)


def summary_rows(points, pipeline):
    """(the sweep's summary table as one {column: value} per point, its columns); a
    string-valued swept parameter is recorded as an index into its list, checked here."""
    columns, _, data = read_table(points)
    for path, values in pipeline.get("sweep", {}).get("parameters", {}).items():
        if path in data and isinstance(values[0], str):
            indices(points, path, data[path], len(values))
    n = len(data[columns[0]]) if columns else 0
    return [{c: float(data[c][r]) for c in columns} for r in range(n)], columns


def missing_columns(what, wanted, columns):
    """A note naming the columns of `wanted` the summary lacks, or "" when it has them all."""
    missing = [c for c in wanted if c not in columns]
    return (f"<p class=note>{html.escape(what)}: the sweep's summary has no column "
            f"{html.escape(', '.join(missing))}</p>" if missing else "")


def sweep_plot(plt, spec, rows, columns, name_of, paper, points):
    """A declared result against a swept parameter: a line per y column and per value of the
    other swept parameters (replicas, a second knob), the paper's values over them."""
    import numpy as np  # here: a page without h5py (and so numpy) still lists the files
    name = spec["name"]
    note = missing_columns(f"sweep plot {name}", [spec["x"]] + spec["y"], columns)
    if note or plt is None:
        return note
    others = other_swept(columns, spec["x"])
    lines = {}
    for row in rows:
        lines.setdefault(tuple(row[c] for c in others), []).append(row)
    logx, logy = spec.get("logx", False), spec.get("logy", False)
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    colour_lines(plt, ax, len(lines) * len(spec["y"]))
    for key, members in sorted(lines.items()):
        members.sort(key=lambda r: r[spec["x"]])
        tag = ", ".join(f"{c.split('.')[-1]} = {name_of(c, v)}" for c, v in zip(others, key))
        for y in spec["y"]:
            x, v, e = (np.array([r.get(c, np.nan) for r in members]) for c in (spec["x"], y, y + "_err"))
            e = uncertainties(None if np.isnan(e).all() else e, points, y + "_err")
            x, v, e = drawable(x, v, e, logx, logy)
            ax.errorbar(x, v, yerr=e, marker="o", markersize=3, capsize=2,
                        label=plain(" ".join(p for p in (y, tag) if p)))
    paper.draw(ax, f"sweep/{name}", lambda x, y, e: drawable(x, y, e, logx, logy))
    ax.set_xlabel(plain(spec.get("xlabel", spec["x"])))
    ax.set_ylabel(plain(spec.get("ylabel", ", ".join(spec["y"]))))
    ax.set_title(plain(spec.get("title", name)))
    return (f"<figure id=\"sweep-{html.escape(name)}\">{inline_svg(plt, fig, ax, logx, logy)}"
            f"<figcaption>{html.escape(name)}</figcaption></figure>")


def speed_error_section(plt, spec, rows, columns, name_of):
    """Run time against the deviation from the finest point (scripts/speed_vs_error.py's
    table), as a table and a log-log chart."""
    knob, quantities = spec["knob"], spec["quantities"]
    wanted = [knob, spec["time"]] + quantities + ([spec["pool"]] if "pool" in spec else [])
    note = missing_columns("speed against error", wanted, columns)
    if note or not rows:  # no rows: a sweep stopped before its first point was done
        return note
    table, series = deviation_table(rows, other_swept(columns, knob), knob, spec["time"],
                                    quantities, name_of)
    if "pool" in spec:
        table, series = pooled(table, knob, quantities, spec["pool"])
    shown = ["group", knob, "seconds"] + [c for q in quantities
                                          for c in (q + "_deviation", q + "_deviation_err")
                                          if c in table[0]]
    body = [[r[c] if isinstance(r[c], str) else number(r[c]) for c in shown] for r in table]
    parts = ["<h3 id=speed_vs_error>speed against error</h3><p>Each point's run time against "
             f"its deviation from the point of smallest {html.escape(knob)} in its group.</p>",
             html_table(shown, body)]
    if plt is not None and series:
        parts.append(speed_error_chart(plt, series))
    return "".join(parts)


def speed_error_chart(plt, series):
    """The log-log chart of `series` {label: [(seconds, |deviation|, knob label)]}; a point
    undefined (NaN) or not positive is not drawn, and a chart of none is a note."""
    import numpy as np
    lines = {}
    for label, points in sorted(series.items()):
        seconds, deviation, _ = zip(*sorted(points))
        x, y, _ = drawable(np.array(seconds, float), np.array(deviation, float), None, True, True)
        if len(x):
            lines[label] = (x, y)
    if not lines:
        return ("<p class=note>speed against error: no point to draw (no deviation finite and "
                "positive)</p>")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for label, (x, y) in lines.items():
        ax.plot(x, y, marker="o", label=label)
    ax.set_xlabel("run time of the point (s)")
    ax.set_ylabel("|deviation from the finest point|")
    return (f"<figure id=speed-vs-error>{inline_svg(plt, fig, ax, True, True)}"
            "<figcaption>speed against error</figcaption></figure>")


def declared_sweep_section(plt, results, pipeline, paper):
    """The sweep plots and the speed-against-error study the pipeline's "report" declares."""
    report = pipeline.get("report", {})
    points = member(results, "sweep/points", "group")
    rows, columns = summary_rows(points, pipeline)
    name_of = value_namer(pipeline)
    parts = [sweep_plot(plt, spec, rows, columns, name_of, paper, points)
             for spec in report.get("sweep_plots", [])]
    if "speed_vs_error" in report:
        parts.append(speed_error_section(plt, report["speed_vs_error"], rows, columns, name_of))
    return "".join(parts)
