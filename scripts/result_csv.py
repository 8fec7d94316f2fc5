"""Reads the CSV tables granpipe writes: an optional '# granpipe ...' provenance line, a header,
then rows of numbers (string sweep values appear as their index in the sweep list)."""
import csv
import math
import os

from input_error import read_pipeline, refuse
from run_manifest import note_written


def read_rows(path, what="table"):
    """Returns (provenance line or "", header, rows of strings)."""
    try:
        with open(path) as f:
            lines = f.readlines()
    except OSError as e:
        # A run of a single point writes no sweep.points.csv: say so where that is the file.
        hint = " (a run of one point writes none)" if path.endswith("sweep.points.csv") else ""
        refuse(f"{path}: expected a granpipe {what}, found none: {e.strerror}{hint}")
    provenance = lines[0].strip() if lines and lines[0].startswith("#") else ""
    rows = list(csv.reader(line for line in lines if not line.startswith("#")))
    if not rows:
        refuse(f"{path}: expected a header row, found an empty table")
    return provenance, rows[0], rows[1:]


def read_table(path):
    """Returns (provenance line or "", header, rows of floats)."""
    provenance, header, rows = read_rows(path)
    numbers = []
    for k, row in enumerate(rows, start=1):
        if len(row) != len(header):
            refuse(f"{path}: data row {k}: expected {len(header)} cells (the header's), "
                   f"found {len(row)}")
        try:
            numbers.append([float(v) for v in row])
        except ValueError:
            refuse(f"{path}: data row {k}: expected numbers, found {row}")
    return provenance, header, numbers


def write_csv(path, first_line, rows):
    """Writes a '#' line and rows to `path` through a partial file renamed over it, so a
    refusal or a crash midway leaves no half-written table; a table written into a run's
    folder joins what --overwrite replaces with the run."""
    partial = path + ".partial"
    with open(partial, "w", newline="") as f:
        f.write(first_line + "\n")
        csv.writer(f).writerows(rows)
    os.replace(partial, path)
    note_written(path)


def read_scalars(path):
    """{name: (value, uncertainty)} of a <group>.scalars.csv (uncertainty nan where none)."""
    _, header, rows = read_rows(path, "scalars table")
    if header[:3] != ["name", "value", "uncertainty"]:
        refuse(f"{path}: expected the columns name,value,uncertainty, found {','.join(header)}")
    table = {}
    for k, row in enumerate(rows, start=1):
        try:
            table[row[0]] = (float(row[1]), float(row[2]))
        except (ValueError, IndexError):
            refuse(f"{path}: data row {k}: expected a name, a value and an uncertainty, "
                   f"found {row}")
    return table


def columns(path, header, rows, *names):
    """The named columns of a table read by read_table, each a list; a missing one refused."""
    for name in names:
        if name not in header:
            refuse(f"{path}: expected a column {name}, found {header[:4]}...")
    return [[r[header.index(name)] for r in rows] for name in names]


def finite_column(path, header, rows, name):
    """A column of a table read by read_table whose every value is a finite number (taps,
    counts: a nan among them would be a wrong index), and that has at least one row."""
    if not rows:
        refuse(f"{path}: expected rows of {name}, found only a header")
    (values,) = columns(path, header, rows, name)
    for k, v in enumerate(values, start=1):
        if not math.isfinite(v):
            refuse(f"{path}: data row {k}, column {name}: expected a finite number, found {v}")
    return values


def sweep_groups(out, over):
    """The sweep points of the run in `out` grouped by every swept parameter but `over` (the
    replicas or realizations pooled): (provenance, header, points, the other swept columns,
    {their values: [point numbers]})."""
    points_path = os.path.join(out, "sweep.points.csv")
    provenance, header, points = read_table(points_path)
    for column in ("point", over):
        if column not in header:
            refuse(f"{points_path}: expected a column {column}, found {header[:4]}...")
    if not points:
        refuse(f"{points_path}: expected rows of sweep points, found only a header")
    row_of_point = {}
    for k, p in enumerate(points, start=1):
        # A point given twice would be pooled twice, or stand for the other's row.
        number = p[header.index("point")]
        if not math.isfinite(number) or number != int(number) or number < 0:
            refuse(f"{points_path}: data row {k}, column point: expected a point number, "
                   f"found {number:g}")
        if number in row_of_point:
            refuse(f"{points_path}: data rows {row_of_point[number]} and {k}: expected each "
                   f"point once, found point {number:g} in both")
        row_of_point[number] = k
    swept = list(read_pipeline(out).get("sweep", {}).get("parameters", {}).keys())
    others = [s for s in swept if s != over and s in header]
    groups = {}
    for p in points:
        key = tuple(p[header.index(s)] for s in others)
        groups.setdefault(key, []).append(int(p[header.index("point")]))
    return provenance, header, points, others, groups

