#!/usr/bin/env python3
"""Pools the ageing squared differences of the compaction analyzer over independent
realizations, the mean of Eq. (5) of the 3D tapping paper, and fits Eq. (6) per waiting time
(its Fig. 5):

  A(t, t_w) = mean over realizations of (<Z>(t_w) - <Z>(t_w + t))^2
  A(t)      = A_inf (1 - 1 / (1 + B ln(1 + t/tau)))

Each realization is a sweep point that differs from the others only in the --over parameter
(default source.params.replica), as for scripts/pool_replicas.py; points that share all other
swept values form a group. Rows of <analyzer>.ageing with the same (t_w, t) are pooled: A is
the mean over the group's realizations, A_err the standard error across them (NaN for one).
Eq. (6) is fitted per group and t_w by scipy's curve_fit, weighted by A_err when every point
has one, from the best point of a grid of B and tau. Writes, beside the input:

  pooled.<analyzer>.ageing.csv       group, t_w, t, realizations, A, A_err
  pooled.<analyzer>.ageing_fits.csv  group, t_w, points, status, A_inf, B, tau with errors

status: 0 fitted, 1 too few points, 2 no convergence, 3 not determined (an error larger than
its parameter); the values are NaN unless fitted. Runs given as parts of one set of
realizations must run one pipeline: a part whose pipeline.json differs from the first's in
anything but its sweep, the --over value, seed, output, name and description is refused; the
pooled tables' first line names every part's run (its seed among them).

    scripts/pool_ageing.py out/tap3d_ageing
    scripts/pool_ageing.py out/ageing_part1 out/ageing_part2   (realizations run in parts)
    scripts/pool_ageing.py out/ageing_r0 out/ageing_r1 ...       (a run per realization)
"""
import argparse
import json
import math
import os

import numpy as np
from scipy.optimize import curve_fit

from input_error import read_pipeline, refuse
from result_csv import read_table, sweep_groups, write_csv


def eq6(t, a_inf, b, tau):
    return a_inf * (1.0 - 1.0 / (1.0 + b * np.log1p(t / tau)))


def pool(tables):
    """tables: list of (path, header, rows). Returns sorted rows (t_w, t, n, A, A_err)."""
    by_key = {}
    for path, header, rows in tables:
        for column in ("t_w", "t", "squared_difference"):
            if column not in header:
                refuse(f"{path}: expected a column {column}, found {header}")
        tw, t, sq = (header.index(c) for c in ("t_w", "t", "squared_difference"))
        for row in rows:
            by_key.setdefault((row[tw], row[t]), []).append(row[sq])
    out = []
    for key in sorted(by_key):
        values = by_key[key]
        n = len(values)
        mean = sum(values) / n
        err = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1) / n) if n > 1 else math.nan
        out.append((*key, n, mean, err))
    return out


# What a fit's status says, as the compaction analyzer's fits: 0 fitted, 1 too few points,
# 2 no convergence, 3 not determined (a parameter's error larger than its value: over taps
# where A has not begun to level off, A_inf and tau_A / B_A run off together).
FITTED, TOO_FEW, NO_CONVERGENCE, NOT_DETERMINED = 0, 1, 2, 3


def grid_start(t, a, weight):
    """Start values: over a grid of B and tau, the A_inf that fits best (linear least squares)
    and the pair whose residual is smallest. From tau = 1 tap, B = 1, curve_fit ran out of
    evaluations on runs where tau_A is hundreds of taps."""
    best = (math.inf, None)
    for b in np.logspace(-2, 3, 26):
        for tau in np.logspace(-1, 5, 31):
            shape = 1.0 - 1.0 / (1.0 + b * np.log1p(t / tau))
            a_inf = np.sum(weight * shape * a) / np.sum(weight * shape * shape)
            residual = np.sum(weight * (a - a_inf * shape) ** 2)
            if residual < best[0]:
                best = (residual, [a_inf, b, tau])
    return best[1]


def fit(rows):
    """Eq. (6) to rows (t_w, t, n, A, A_err) of one t_w: status, values and errors (NaN unless
    fitted)."""
    t = np.array([r[1] for r in rows])
    a = np.array([r[3] for r in rows])
    err = np.array([r[4] for r in rows])
    if len(t) <= 3:
        return [TOO_FEW] + [math.nan] * 6
    weighted = bool(np.all(np.isfinite(err)) and np.all(err > 0))
    sigma = err if weighted else None
    try:
        p, cov = curve_fit(eq6, t, a, p0=grid_start(t, a, 1.0 / err**2 if weighted else np.ones_like(t)),
                           sigma=sigma, absolute_sigma=weighted,
                           bounds=([-np.inf, 0.0, 1e-9], np.inf), maxfev=10000)
    except (RuntimeError, ValueError):
        return [NO_CONVERGENCE] + [math.nan] * 6
    e = np.sqrt(np.diag(cov))
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(e))) or np.any(e > np.abs(p)):
        return [NOT_DETERMINED] + [math.nan] * 6
    return [FITTED, p[0], e[0], p[1], e[1], p[2], e[2]]


def write(path, provenance, header, rows):
    write_csv(path, f"{provenance} pooled by scripts/pool_ageing.py", [header] + rows)
    print(f"{path}: {len(rows)} rows")


def value_at(pipeline, path):
    """The value at a dotted path (source.params.replica) of a resolved pipeline, or None."""
    value = pipeline
    for part in path.split("."):
        value = value.get(part) if isinstance(value, dict) else None
    return value


def run_realizations(out, analyzer, over):
    """The other swept parameters of the run in `out` and {their values: [(realization, its
    ageing table's path)]}. A run of one point writes no sweep.points.csv and its tables
    without a point_NNN. prefix: it is one realization, numbered in its resolved pipeline."""
    if not os.path.exists(os.path.join(out, "sweep.points.csv")):
        value = value_at(read_pipeline(out), over)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            refuse(f"{os.path.join(out, 'pipeline.json')}: expected a number at {over} "
                   f"(a run of one realization), found {value!r}")
        return [], {(): [(float(value), os.path.join(out, f"{analyzer}.ageing.csv"))]}
    _, header, points, others, by_key = sweep_groups(out, over)
    value_of = {int(p[header.index("point")]): p[header.index(over)] for p in points}
    return others, {key: [(value_of[point], os.path.join(out, f"point_{point:03d}.{analyzer}.ageing.csv"))
                          for point in members]
                    for key, members in by_key.items()}


# What may differ between the parts of one set of realizations: the sweep that numbers them
# (and groups them by its other parameters, whose values each part's pipeline.json gives as
# its point 0's), the realization number, the seed, the output folder, name and description.
PART_KEYS = ("sweep", "seed", "output", "name", "description")


def path_parts(path):
    """"analyzers[0].params.eta" -> ["analyzers", 0, "params", "eta"]."""
    parts = []
    for name in path.split("."):
        key, *indices = name.replace("]", "").split("[")
        parts.append(key)
        parts += [int(i) for i in indices if i.isdigit()]
    return parts


def without(value, parts):
    """A copy of the JSON value without the entry at `parts` (where it has one)."""
    if not parts:
        return None
    head, rest = parts[0], parts[1:]
    if isinstance(value, dict) and head in value:
        copy = dict(value)
        if rest:
            copy[head] = without(value[head], rest)
        else:
            del copy[head]
        return copy
    if isinstance(value, list) and isinstance(head, int) and head < len(value):
        copy = list(value)
        copy[head] = without(value[head], rest) if rest else None
        return copy
    return value


def without_part_keys(pipeline, swept):
    """The pipeline as every part of one set of realizations must share it: without the
    PART_KEYS and the parameters the realizations are numbered and grouped by (`swept`)."""
    kept = {k: v for k, v in pipeline.items() if k not in PART_KEYS}
    for path in swept:
        kept = without(kept, path_parts(path))
    return kept


def first_difference(a, b, path=""):
    """The first dotted path where two JSON values differ, or None."""
    if isinstance(a, dict) and isinstance(b, dict):
        for key in sorted(set(a) | set(b)):
            found = first_difference(a.get(key), b.get(key), f"{path}.{key}" if path else key)
            if found:
                return found
        return None
    return None if a == b else path


def refuse_other_pipelines(outs, swept):
    """Parts of other pipelines (another N, another epsilon) pooled as one set of realizations
    gave one plausible A, exit 0: every part must run the first one's pipeline but for the
    `swept` parameters the realizations are numbered and grouped by."""
    pipelines = [read_pipeline(out) for out in outs]
    first = without_part_keys(pipelines[0], swept)
    for out, pipeline in zip(outs[1:], pipelines[1:]):
        other = without_part_keys(pipeline, swept)
        where = first_difference(first, other)
        if where:
            refuse(f"{os.path.join(out, 'pipeline.json')}: {where}: expected the value of "
                   f"{outs[0]} (parts of one set of realizations), found "
                   f"{json.dumps(value_at(other, where))} against "
                   f"{json.dumps(value_at(first, where))}")


def realization_tables(outs, analyzer, over):
    """The other swept columns and {their values: [(path, header, rows)]} of the ageing tables
    of every realization in the runs `outs` (one pipeline's realizations run in several
    parts, as sweeps or as runs of one realization each); a realization met twice is refused:
    pooled twice, it would weigh double."""
    others, groups, seen = None, {}, {}
    for out in outs:
        run_others, by_key = run_realizations(out, analyzer, over)
        if others is None:
            others = run_others
        elif run_others != others:
            refuse(f"{out}: expected the swept parameters {others} of {outs[0]}, found {run_others}")
        for key, members in by_key.items():
            for value, path in members:
                if (key, value) in seen:
                    refuse(f"{out}: {over} = {value:g}: expected each realization once, found it "
                           f"in {seen[(key, value)]} too")
                seen[(key, value)] = out
                if not os.path.exists(path):
                    refuse(f"{path}: expected the ageing table of {over} = {value:g}, found no file")
                groups.setdefault(key, []).append((path, *read_table(path)))
    # A run of one point groups by nothing: its swept values are compared as any other.
    refuse_other_pipelines(outs, {over, *others})
    return others, groups


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", nargs="+",
                    help="output directory of a sweep run over realizations (several: its parts, "
                         "pooled into the first)")
    ap.add_argument("--analyzer", default="compaction", help="name of the compaction analyzer in the pipeline")
    ap.add_argument("--over", default="source.params.replica", help="the swept parameter that numbers the realizations")
    args = ap.parse_args()
    others, groups = realization_tables(args.out, args.analyzer, args.over)
    pooled_rows, fit_rows = [], []
    # Every part's run (its seed among them), not the last table's alone.
    runs = []
    for found in groups.values():
        for _, line, _, _ in found:
            run = line.lstrip("# ")
            if run not in runs:
                runs.append(run)
    provenance = "# " + " + ".join(runs)
    for gkey, found in sorted(groups.items()):
        group = ", ".join(f"{s.split('.')[-1]}={v:g}" for s, v in zip(others, gkey)) or "all"
        rows = pool([(path, header, table) for path, _, header, table in found])
        pooled_rows += [[group, *r] for r in rows]
        for t_w in sorted({r[0] for r in rows}):
            one = [r for r in rows if r[0] == t_w]
            fit_rows.append([group, t_w, len(one), *fit(one)])
    base = os.path.join(args.out[0], f"pooled.{args.analyzer}")
    write(base + ".ageing.csv", provenance, ["group", "t_w", "t", "realizations", "A", "A_err"], pooled_rows)
    write(base + ".ageing_fits.csv", provenance,
          ["group", "t_w", "points", "status", "A_inf", "A_inf_err", "B", "B_err", "tau", "tau_err"],
          fit_rows)


if __name__ == "__main__":
    main()
