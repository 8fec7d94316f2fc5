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
import json
import os
import re
import sys
import tempfile
import warnings

from paper_values import PaperValues, paper_problem
from report_configuration import configuration_section
from report_h5 import (HDF5_ERRORS, Damaged, attr_number, attr_numbers, attr_text, attr_texts,
                       column, member, members, not_a_file, producer, scalar, unreadable)
from report_parts import TABLE_ROWS_SHOWN, html_table, number, table_section, with_error
from report_plots import plots_section
from report_sweep import report_problem, sweep_section
from run_manifest import note_written


def refuse(message):
    """One line, as granpipe's own refusals (the report is its subcommand), and exit 2."""
    print(f"granpipe: {message}", file=sys.stderr)
    sys.exit(2)


def scalars_section(group):
    rows = []
    for name, item in members(group):
        if attr_text(item, "kind", "") != "scalar":
            continue
        value = scalar(group, name)
        rows.append([name, with_error(value, float(attr_number(item, "uncertainty"))),
                     attr_text(item, "unit"), attr_text(item, "doc")])
    return html_table(["scalar", "value", "unit", "what"], rows) if rows else ""


def fit_section(name, group, producer_group):
    names = attr_texts(group, "names")
    values = column(group, "values", len(names), "one per name in attribute names")
    errors = column(group, "errors", len(names), "one per name in attribute names")
    rows = [[p, with_error(v, e)] for p, v, e in zip(names, values, errors)]
    chi2, dof = float(attr_number(group, "chi2")), attr_number(group, "dof", integer=True)
    return (f"<h4>fit {html.escape(name)}</h4><p><code>{html.escape(attr_text(group, 'model'))}"
            f"</code> (χ² = {number(chi2)}, {dof} degrees of freedom)</p>"
            + fit_status(name, producer_group) + html_table(["parameter", "value"], rows))


def fit_status(name, producer_group):
    """The fit's status where its producer records one (`<name>_status`): a fit not made
    showed every parameter undefined and said nothing of why, the reason elsewhere."""
    status = f"{name}_status"
    if status not in producer_group or attr_text(producer_group[status], "kind", "") != "scalar":
        return ""
    code = scalar(producer_group, status)
    return (f"<p>status {number(code)}: {html.escape(attr_text(producer_group[status], 'doc'))}"
            "</p>")


def histogram_section(name, group):
    values = column(group, "values")
    edges = column(group, "edges", len(values) + 1, "one more than values")
    # Errors are optional: a histogram of counts without them is shown without ±.
    errors = (column(group, "errors", len(values), "one per value") if "errors" in group
              else [float("nan")] * len(values))
    rows = [[f"{number(edges[k])} – {number(edges[k + 1])}", with_error(values[k], errors[k])]
            for k in range(len(values))]
    # A cut histogram said nothing of the bins left out (arches' spans: every arch in bins 22
    # to 38 of 39, the 12 shown all 0).
    more = ""
    if len(rows) > TABLE_ROWS_SHOWN:
        held = [k for k in range(len(values)) if values[k] != 0]  # NaN too: undefined, not 0
        rows = [rows[k] for k in held[:TABLE_ROWS_SHOWN]]
        more = (f" — every one of the {len(values)} bins is 0" if not held else
                f" — {len(rows)} of the {len(values)} bins shown, from the lowest of those not "
                f"0 (the other {len(values) - len(held)} are 0); every bin in results.h5")
    return (f"<h4>histogram {html.escape(name)}</h4><p>{html.escape(attr_text(group, 'doc'))}"
            f"{more}</p>" + html_table([attr_text(group, "xlabel"), "value"], rows))


POINT_GROUP = re.compile(r"point_[0-9]+")


def producers(results):
    """(path, group) of every producer: at the top, or in the point_NNN groups of a sweep
    whose sweep group is not written yet (a sweep stopped: its points showed as headings
    over nothing)."""
    for name in results:
        group = producer(results, name)
        if POINT_GROUP.fullmatch(name):
            yield from ((f"{name}/{inner}", producer(group, inner)) for inner in group)
        else:
            yield name, group


def producer_section(plt, path, group, paper, partial):
    parts = [f"<h3 id=\"{html.escape(path)}\">{html.escape(path)}</h3>",
             plots_section(plt, [("", group)], path, paper), scalars_section(group)]
    for name, item in members(group):
        kind = attr_text(item, "kind", "")
        if kind == "table":
            parts.append(table_section(path, name, item, partial=partial))
        elif kind == "fit":
            parts.append(fit_section(name, member(group, name, "group"), group))
        elif kind == "histogram":
            parts.append(histogram_section(name, member(group, name, "group")))
    return "".join(parts)


PROVENANCE = [("pipeline_name", attr_text), ("granpipe_version", attr_text),
              ("git_commit", attr_text), ("seed", attr_number), ("threads", attr_number),
              ("started", attr_text), ("wall_seconds", attr_number)]


def provenance_section(results, partial, state):
    rows = [[k, str(read(results, k))] for k, read in PROVENANCE if k in results.attrs]
    if partial:  # the partial file holds 0, which read as a run of no time
        rows = [[k, "not measured (the run has not finished)" if k == "wall_seconds" else v]
                for k, v in rows]
    if "stage_names" in results.attrs:  # where the time went (summed over a sweep's points)
        names = attr_texts(results, "stage_names")
        seconds = attr_numbers(results, "stage_seconds", len(names), "one per stage")
        rows += [[f"seconds in {name}", number(s)] for name, s in zip(names, seconds)]
    note = (f"<p class=note>this run {html.escape(state)}: the results so far, from "
            "results.partial.h5</p>" if partial else "")
    return "<h2>Provenance</h2>" + note + html_table(None, rows)


def run_state(run, log):
    """What became of an unfinished run, as its marker and run.log say: "is still going (or
    was killed)", "was interrupted by SIGTERM ...", "failed: ..."; a page of each read "has
    not finished (or was stopped)" alike."""
    try:
        with open(os.path.join(run, ".granpipe-run"), errors="replace") as f:
            status = json.loads(f.read(4096).strip() or "{}").get("status", "")
    except (OSError, ValueError, AttributeError):
        status = ""
    said = [line.strip() for line in log if line.startswith(("interrupted by ", "failed: "))]
    if status == "running":
        return "is still going (or was killed)"
    if status == "interrupted":
        return f"was {said[-1]}" if said else "was interrupted"
    if status == "failed":
        return said[-1] if said else "failed"
    return "has not finished (or was stopped)"


def log_lines(run):
    """run.log's lines (none where there is no log)."""
    try:
        with open(os.path.join(run, "run.log"), errors="replace") as f:
            return f.read().splitlines()
    except OSError:
        return []


MOST_WARNINGS_SHOWN = 20


def warnings_section(log):
    """run.log's warnings (undefined results, left-out inputs), which the page left out."""
    said = [line for line in log if line.startswith("warning: ")]
    if not said:
        return ""
    more = (f"<p>the first {MOST_WARNINGS_SHOWN} of {len(said)}; every one in run.log</p>"
            if len(said) > MOST_WARNINGS_SHOWN else "")
    items = "".join(f"<li>{html.escape(line[len('warning: '):])}</li>"
                    for line in said[:MOST_WARNINGS_SHOWN])
    return f"<h2>Warnings</h2>{more}<ul>{items}</ul>"


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
            what = not_a_file(path)  # h5py would wait on a FIFO for ever
            if what:
                refuse(f"{path}: expected a granpipe results file, found {what}")
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
        # A point without an uncertainty (NaN) draws no error bar, as meant; matplotlib says
        # so on stderr for each, past granpipe's --quiet.
        warnings.filterwarnings("ignore", message=".*converting a masked element to nan",
                                category=UserWarning)
        return plt
    except ImportError:
        return None


def read_run_pipeline(run):
    """(text, object) of the run's pipeline.json; refused in one line where the page could not
    be drawn from it: not UTF-8, no JSON, no object, and the problems of pipeline_problem."""
    path = os.path.join(run, "pipeline.json")
    try:
        with open(path, "rb") as f:
            text = f.read().decode("utf-8")
        pipeline = json.loads(text)
    except OSError as e:
        refuse(f"{path}: expected the pipeline of a granpipe run, found none: {e.strerror}")
    except UnicodeDecodeError as e:
        refuse(f"{path}: expected the pipeline of a granpipe run (UTF-8 JSON), found byte "
               f"0x{e.object[e.start]:02x} at offset {e.start}, which is not UTF-8")
    except ValueError as e:
        refuse(f"{path}: expected the pipeline of a granpipe run, found malformed JSON: {e}")
    if not isinstance(pipeline, dict):
        refuse(f"{path}: expected the pipeline of a granpipe run (a JSON object), found a JSON "
               f"{type(pipeline).__name__}")
    problem = pipeline_problem(pipeline)
    if problem:
        refuse(f"{path}: {problem}")
    return text, pipeline


def pipeline_problem(pipeline):
    """What is wrong with the sections of the pipeline the page is drawn from, as "where:
    expected ..., found ...", or ""."""
    sections = [("sweep", pipeline.get("sweep", {})), ("report", pipeline.get("report", {}))]
    if isinstance(sections[0][1], dict):
        sections.append(("sweep.parameters", sections[0][1].get("parameters", {})))
    for where, value in sections:
        if not isinstance(value, dict):
            return f"{where}: expected an object, found {json.dumps(value)}"
    for name, values in sections[2][1].items():
        if not (isinstance(values, list) and values):  # a string parameter is named by values[0]
            return f"sweep.parameters.{name}: expected a list of values, found {json.dumps(values)}"
    report = sections[1][1]
    return paper_problem(report.get("paper", [])) or report_problem(report)


def report_body(run, pipeline_text, pipeline, results, partial, note, plt):
    paper = PaperValues(pipeline)
    parts = [f"<p class=note>{html.escape(note)}</p>" if note else ""]
    if results is not None:
        log = log_lines(run)
        parts.append(provenance_section(results, partial, run_state(run, log) if partial else ""))
        parts.append(warnings_section(log))
        parts.append("<h2>Results</h2>")
        if plt is None:
            parts.append("<p class=note>plots not drawn: matplotlib is not installed</p>")
        if "sweep" in results:
            parts.append(sweep_section(plt, results, pipeline, paper))
        else:
            parts += [producer_section(plt, path, group, paper, partial)
                      for path, group in producers(results)]
        if plt is not None:
            parts.append(paper.notes())
        parts.append(configuration_section(plt, run))
    csvs = sorted(f for f in os.listdir(run) if f.endswith(".csv"))
    parts.append("<h2>Files</h2><ul>" + "".join(
        f"<li><a href=\"{html.escape(f)}\">{html.escape(f)}</a></li>" for f in csvs) + "</ul>")
    parts.append(f"<h2>Pipeline as run</h2><pre>{html.escape(pipeline_text)}</pre>")
    return "".join(parts)


def is_our_page(path):
    # A FIFO would block the read, a directory is not ours, and a symlink is the user's
    # (it was replaced by a file, and listed as the run's).
    if os.path.islink(path) or not os.path.isfile(path):
        return False
    try:
        with open(path, errors="replace") as f:
            return GENERATOR in f.read(4096)
    except OSError:
        return False


def main(run):
    if not os.path.isfile(os.path.join(run, "pipeline.json")):
        refuse(f"{run}/pipeline.json: expected the pipeline of a granpipe run, found none")
    pipeline_text, pipeline = read_run_pipeline(run)
    results, drawn_from_partial, note = read_results(run)
    try:
        name = attr_text(results, "pipeline_name") if results is not None else os.path.basename(run)
        body = report_body(run, pipeline_text, pipeline, results, drawn_from_partial, note,
                           pyplot())
    except Damaged as e:  # results.h5 or frames.h5 not as granpipe writes them
        refuse(str(e))
    except HDF5_ERRORS as e:  # an object of results.h5 HDF5 cannot read (frames.h5: Damaged)
        refuse(str(unreadable(results.filename, e)))
    html_text = page(f"granpipe run {name}", body)
    target = os.path.join(run, "report.html")
    if os.path.lexists(target) and not is_our_page(target):
        found = ("a symbolic link" if os.path.islink(target) else
                 "a directory" if os.path.isdir(target) else "another file")
        refuse(f"{target}: expected a report granpipe wrote, found {found}; it is left as it is "
               "(move it away to have the report)")
    completed = os.path.join(run, "results.h5")
    partial = None
    try:
        # A name of its own, created exclusively (two reports of one run at once: one wins
        # whole; a symlink planted at the name is not written through; a temporary left by a
        # killed report, its pid used again, is not in the way).
        descriptor, partial = tempfile.mkstemp(prefix="report.html.", suffix=".tmp", dir=run)
        os.fchmod(descriptor, 0o666 & ~current_umask())  # mkstemp's 0600 would hide the page
        with os.fdopen(descriptor, "w") as f:
            f.write(html_text)
        # The run completed while the page was drawn from the results so far: it removed
        # the page of those, and this one would land as stale (or over the final one).
        stale = drawn_from_partial and os.path.exists(completed)
        if stale:
            os.remove(partial)
        else:
            landed = os.stat(partial).st_ino
            os.replace(partial, target)
            stale = drawn_from_partial and os.path.exists(completed) and ours(target, landed)
        if not stale:
            note_written(target)
    except OSError as e:  # a full disk, a folder not ours to write: the run's files stay
        if partial is not None and os.path.lexists(partial):
            os.remove(partial)
        refuse(f"{e.filename or target}: cannot write the report: {e.strerror}")
    if stale:  # drawn again, from the results now complete (once: results.h5 is read first)
        main(run)


def current_umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def ours(target, inode):
    """Whether `target` is still the page this process wrote (the run, completing, may have
    removed it since, or the final page replaced it)."""
    try:
        return os.stat(target).st_ino == inode
    except FileNotFoundError:
        return True  # removed as stale: this page was, so draw the complete one


if __name__ == "__main__":
    if len(sys.argv) != 2:
        refuse("usage: report.py RUN_DIR")
    main(sys.argv[1])
