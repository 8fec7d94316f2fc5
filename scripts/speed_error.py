"""Speed against error of a sweep over a resolution knob (a time step, a threshold): each
point's run time against its deviation from the finest point of its group. Shared by
scripts/speed_vs_error.py (the table and its chart) and report.py (the chart in report.html).

`points` are the sweep's summary rows as {column: value}; `swept` the swept columns other
than the knob (each combination of their values is a group, with its own reference: the
point with the smallest knob); `name_of(column, value)` renders a swept value."""
import math
import statistics

from report_parts import number


def other_swept(header, knob):
    """The swept columns of a sweep's summary header other than the knob."""
    return [h for h in header[1:] if h != knob and h.startswith(("source.params.", "analyzers["))]


def value_namer(pipeline):
    """name_of(column, value) for the pipeline as run: a string-valued sweep parameter is
    recorded as its index in the sweep's list, and named by its string."""
    lists = pipeline.get("sweep", {}).get("parameters", {})
    # A number as the report writes one: seeds 12345678 and 12345679 both read 1.23457e+07.
    return lambda s, v: lists[s][int(v)] if s in lists and isinstance(lists[s][0], str) else number(v)


def deviation_table(points, swept, knob, time, quantities, name_of):
    """(rows, series): a row per point, finest last in each group, with the seconds, each
    quantity, its |deviation| and the reference's standard error; series {label: [(seconds,
    |deviation|, knob label)]} without the references themselves."""
    groups = {}
    for p in points:
        groups.setdefault(tuple(p[s] for s in swept), []).append(p)
    rows, series = [], {}
    for key, members in sorted(groups.items()):
        ref = min(members, key=lambda p: p[knob])
        tag = ", ".join(f"{s.split('.')[-1]}={name_of(s, v)}" for s, v in zip(swept, key)) or "all"
        for p in sorted(members, key=lambda p: -p[knob]):
            row = {"group": tag, knob: p[knob], "seconds": p[time]}
            for q in quantities:
                row[q] = p[q]
                row[q + "_deviation"] = abs(p[q] - ref[q])
                row[q + "_reference_err"] = ref.get(q + "_err", float("nan"))
                if p is not ref:
                    series.setdefault(f"{q} ({tag})", []).append(
                        (p[time], abs(p[q] - ref[q]), f"{knob}={p[knob]:g}"))
            rows.append(row)
    return rows, series


def pooled(rows, knob, quantities, pool):
    """The rows averaged over the values of the swept parameter `pool` (replicas): one row
    per (other groups, knob) with the mean seconds and mean |deviation| ± its standard error."""
    pool_name = pool.split(".")[-1]
    keep = lambda tag: ", ".join(t for t in tag.split(", ") if not t.startswith(pool_name + "=")) or "all"
    groups = {}
    for r in rows:
        groups.setdefault((keep(r["group"]), r[knob]), []).append(r)
    out, series = [], {}
    for (tag, value), members in sorted(groups.items(), key=lambda kv: (kv[0][0], -kv[0][1])):
        row = {"group": tag, knob: value, "replicas": len(members),
               "seconds": statistics.fmean(m["seconds"] for m in members)}
        for q in quantities:
            devs = [m[q + "_deviation"] for m in members]
            row[q + "_deviation"] = statistics.fmean(devs)
            row[q + "_deviation_err"] = (statistics.stdev(devs) / math.sqrt(len(devs))
                                         if len(devs) > 1 else float("nan"))
            if row[q + "_deviation"] > 0:
                series.setdefault(f"{q} ({tag})", []).append(
                    (row["seconds"], row[q + "_deviation"], f"{knob}={value:g}"))
        out.append(row)
    return out, series
