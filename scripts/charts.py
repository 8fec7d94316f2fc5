"""The x-y charts of the scripts beside it, drawn with matplotlib (Agg backend, no display).

Each series is drawn with the gid "series-<k>" (k in the order of the legend), so a test can
find its points in an SVG. SVG output carries no date and a fixed hash salt: drawing the same
data twice gives the same file."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

from run_manifest import note_written  # noqa: E402

plt.rcParams.update({"svg.fonttype": "none", "svg.hashsalt": "granpipe", "font.size": 10})
SIZE = (8.0, 4.6)  # inches


def _save(fig, path):
    fig.savefig(path, metadata={"Date": None} if path.endswith(".svg") else None, bbox_inches="tight")
    plt.close(fig)
    note_written(path)


def line_chart(series, reference, xlabel, ylabel, path, reference_label="steady state (constant A)"):
    """series: {name: [(x, y, err)]}, each drawn as a line through its points with error bars;
    reference: [(x, y, err)] drawn as black squares (err may be nan), named reference_label."""
    fig, ax = plt.subplots(figsize=SIZE)
    for k, (name, points) in enumerate(sorted(series.items())):
        points = sorted(points)
        xs, ys, errs = zip(*points)
        errs = [e if math.isfinite(e) else 0.0 for e in errs]
        ax.errorbar(xs, ys, yerr=errs, marker="o", markersize=3, capsize=2, label=name, gid=f"series-{k}")
    if reference:
        xs, ys, errs = zip(*reference)
        errs = [e if math.isfinite(e) else 0.0 for e in errs]
        ax.errorbar(xs, ys, yerr=errs, linestyle="none", marker="s", markersize=4, color="black",
                    capsize=2, label=reference_label, gid="reference")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=9)
    _save(fig, path)


def loglog_chart(series, xlabel, ylabel, path):
    """series: {name: [(x, y, label)]}, positive x and y, drawn as lines with markers on log axes;
    points with x or y not positive cannot be drawn there and are left out."""
    fig, ax = plt.subplots(figsize=SIZE)
    for k, (name, points) in enumerate(sorted(series.items())):
        points = [(x, y) for x, y, _ in sorted(points) if x > 0 and y > 0]
        if points:
            xs, ys = zip(*points)
            ax.plot(xs, ys, marker="o", markersize=4, label=name, gid=f"series-{k}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=9)
    _save(fig, path)


def compaction_chart(series, fits, ylabel, path):
    """Fig. 2 of the 3D tapping paper: series {name: [(t, y)]} against the number of taps t on a
    log axis (left, t > 0) and a linear one (right); fits {name: [(t, y)]} drawn dotted."""
    fig, axes = plt.subplots(1, 2, figsize=(SIZE[0] * 1.4, SIZE[1]))
    for ax, log in zip(axes, (True, False)):
        for k, (name, points) in enumerate(sorted(series.items())):
            points = [(t, y) for t, y in sorted(points) if t > 0 or not log]
            if not points:
                continue
            ts, ys = zip(*points)
            line, = ax.plot(ts, ys, linewidth=1, label=name, gid=f"series-{k}")
            if fits.get(name):
                ft, fy = zip(*[(t, y) for t, y in sorted(fits[name]) if t > 0 or not log])
                ax.plot(ft, fy, linestyle=":", linewidth=2, color=line.get_color(), gid=f"fit-{k}")
        if log:
            ax.set_xscale("log")
        ax.set_xlabel("taps t")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3, which="both")
    axes[1].legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=9)
    _save(fig, path)


def curves_chart(series, xlabel, ylabel, path, log_y=False, log_x=False):
    """series: {name: [(x, y)]}, each a line in the order given (the legend keeps it)."""
    fig, ax = plt.subplots(figsize=SIZE)
    for k, (name, points) in enumerate(series.items()):
        if points:
            xs, ys = zip(*points)
            ax.plot(xs, ys, linewidth=1, label=name, gid=f"series-{k}")
    if log_y:
        ax.set_yscale("log")
    if log_x:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=9)
    _save(fig, path)
