"""Reads the CSV tables granpipe writes: an optional '# granpipe ...' provenance line, a header,
then rows of numbers (string sweep values appear as their index in the sweep list)."""
import csv


def read_table(path):
    """Returns (provenance line or "", header, rows of floats)."""
    with open(path) as f:
        lines = f.readlines()
    provenance = lines[0].strip() if lines and lines[0].startswith("#") else ""
    rows = list(csv.reader(line for line in lines if not line.startswith("#")))
    if not rows:
        raise SystemExit(f"{path}: expected a header row, found an empty table")
    return provenance, rows[0], [[float(v) for v in row] for row in rows[1:]]
