"""The pieces of report.html: numbers ("undefined" for NaN, never a plausible zero), HTML
tables (results.h5's read by report_h5), and matplotlib figures inlined as SVG."""
import html
import io
import math
import numbers

from report_h5 import attr_text, damaged, read_table

TABLE_ROWS_SHOWN = 12  # a long table is cut on the page; its CSV file has every row
MARKED_POINTS = 60  # a line of more points is drawn without a marker at each (page size)
MAX_LEGEND_LINES = 12  # more lines than this go in a legend beside the plot, not over it
LEGEND_ROWS = 24  # a column of the legend beside the plot


# Whole numbers below this are shown whole: a count of 1412032 trials read "1.41203e+06".
WHOLE_SHOWN_BELOW = 1e15


def number(x):
    if isinstance(x, numbers.Integral):
        return str(int(x))
    x = float(x)  # numpy's float32 too
    if math.isnan(x):
        return "undefined"
    if x.is_integer() and abs(x) < WHOLE_SHOWN_BELOW:
        return str(int(x))
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


def table_section(producer, name, group, rows_shown=TABLE_ROWS_SHOWN, partial=False):
    """A table's first rows; the rest in its CSV, which a run writes when it ends (a partial
    run's report linked CSVs that were not there)."""
    columns, units, data = read_table(group)
    n = len(data[columns[0]]) if columns else 0
    header = [f"{c} ({u})" if u else c for c, u in zip(columns, units)]
    rows = [[number(data[c][r]) for c in columns] for r in range(min(n, rows_shown))]
    csv = html.escape(csv_name(producer, name))  # names from the file: no markup of theirs
    where = ("results.partial.h5 (the CSVs are written when the run ends)" if partial
             else f"<a href=\"{csv}\">{csv}</a>")
    more = (f" — the first {rows_shown} of {n} rows; every row in {where}"
            if n > rows_shown else f" — {n} rows")
    return (f"<h4>table {html.escape(name)}</h4><p>{html.escape(attr_text(group, 'doc'))}{more}"
            f"</p>" + html_table(header, rows))


def axis_label(label, unit):
    """The plugin's label, with the column's unit when the label does not give one."""
    return f"{label} ({unit})" if unit and unit not in label else label


def plain(text):
    """A label from a file for matplotlib: its mathtext ("$\\phi$") where that is valid, else
    the text as it is, its "$" escaped (mathtext matplotlib cannot parse raises when drawn)."""
    from matplotlib import cbook
    from matplotlib.mathtext import MathTextParser
    if not cbook.is_math_text(text):
        return text
    try:
        MathTextParser("path").parse(text)
        return text
    except ValueError:
        return text.replace("$", r"\$")


def uncertainties(e, group, name):
    """`e`, the uncertainties of the column `name` of `group` (None: none); a negative one is
    damage (NaN: undefined, drawn without a bar)."""
    import numpy as np
    if e is not None and (e < 0).any():
        raise damaged(group, "uncertainties >= 0 (or NaN)", e[np.argmax(e < 0)],
                      path=f"{group.name.rstrip('/')}/{name}")
    return e


def drawable(x, y, e, logx, logy):
    """The points a plot can show: finite, and positive on a log axis."""
    import numpy as np
    keep = np.isfinite(x) & np.isfinite(y)
    if logx:
        keep &= x > 0
    if logy:
        keep &= y > 0
    return x[keep], y[keep], None if e is None else e[keep]


DISTINCT_COLOURS = 10  # matplotlib's default colour cycle


def colour_lines(plt, ax, lines):
    """Colours for `lines` lines to come, each its own: the default cycle repeats every 10
    (a sweep's lines shared colours)."""
    if lines > DISTINCT_COLOURS:
        import numpy as np
        ax.set_prop_cycle(color=plt.cm.viridis(np.linspace(0.0, 0.95, lines)))


def inline_svg(plt, fig, ax, logx, logy):
    """The figure as an SVG element to inline (log axes and a legend as asked), closed."""
    if logx:
        ax.set_xscale("log")
    if logy:
        ax.set_yscale("log")
    labelled = ax.get_legend_handles_labels()[0]  # none in a plot of no point
    beside = len(labelled) > MAX_LEGEND_LINES
    if beside:  # a sweep's 16 lines and more had no legend at all: which line was which?
        legend = ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1.0),
                           ncol=math.ceil(len(labelled) / LEGEND_ROWS))
        # Out of tight_layout, which shrank the plot to a quarter of the figure to make room,
        # and back in for the saving, whose canvas grows around it (bbox_inches "tight"),
        # else it was cut off.
        legend.set_in_layout(False)
    elif labelled:
        ax.legend(fontsize="small")
    fig.tight_layout()
    if beside:
        legend.set_in_layout(True)
    out = io.StringIO()
    fig.savefig(out, format="svg", metadata={"Date": None},  # the same run, the same page
                bbox_inches="tight" if beside else None)
    plt.close(fig)
    svg = out.getvalue()
    return svg[svg.index("<svg"):]  # inline: without the XML prolog
