"""report.html's declared plots: every plot a plugin declared through Results, one line per
y column (per sweep point in a sweep), axis units from the table, error bars or bands from
<y>_err columns, and the paper's values over them where the pipeline declares some."""
import html

from report_h5 import attr_number, attr_text, attr_texts, damaged, linked, member, read_table
from report_parts import (MARKED_POINTS, axis_label, colour_lines, drawable, inline_svg, plain,
                          uncertainties)


def declared_columns(declared, group):
    """{column: values} and {column: unit} of the plot's table `group`, which has the columns
    the plot `declared` names (both come from one plugin: a column missing is damage)."""
    columns, units, data = read_table(group)
    for attr, names in (("x", [attr_text(declared, "x")]), ("y", attr_texts(declared, "y"))):
        for name in names:
            if name not in data:
                raise damaged(declared, f"a column of {group.name}", f'"{name}"', attr)
    return data, dict(zip(columns, units))


def plot_svg(plt, declared, tables, plot, paper):
    """The declared plot as an inline SVG element, or None when no point can be drawn: one
    line per y column of each (label, table) of `tables` (one table in a single run, one per
    sweep point in a sweep), and the paper's values for `plot` ("producer/name") over them."""
    x_name = attr_text(declared, "x")
    logx = bool(attr_number(declared, "logx", integer=True))
    logy = bool(attr_number(declared, "logy", integer=True))
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    colour_lines(plt, ax, len(tables) * len(attr_texts(declared, "y")))
    drawn = 0
    for label, group in tables:
        data, unit_of = declared_columns(declared, group)
        for y_name in attr_texts(declared, "y"):
            e = uncertainties(data.get(f"{y_name}_err"), group, f"{y_name}_err")
            x, y, e = drawable(data[x_name], data[y_name], e, logx, logy)
            drawn += len(x)
            line_label = plain(" ".join(part for part in (label, y_name) if part))
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
    paper.draw(ax, plot, lambda x, y, e: drawable(x, y, e, logx, logy))
    ax.set_xlabel(plain(axis_label(attr_text(declared, "xlabel"), unit_of[x_name])))
    # The y columns' unit where they share one (only x had its unit: compaction's <Z> in R
    # read as a bare number).
    y_units = {unit_of[y] for y in attr_texts(declared, "y")}
    y_unit = y_units.pop() if len(y_units) == 1 else ""
    ax.set_ylabel(plain(axis_label(attr_text(declared, "ylabel"), y_unit)))
    ax.set_title(plain(attr_text(declared, "title")))
    return inline_svg(plt, fig, ax, logx, logy)


def plots_section(plt, groups, producer, paper):
    """Every plot the producer declared; `groups` is [(label, its results group)]: the run's
    group, or one per sweep point, drawn together."""
    declared_in = groups[0][1]
    if "_plots" not in declared_in:
        return ""
    if plt is None:
        return "<p class=note>plots not drawn: matplotlib is not installed</p>"
    parts = []
    plots = member(declared_in, "_plots", "group")
    for name in plots:
        declared = member(plots, name, "group")
        table_name = attr_text(declared, "table")
        tables = [(label, linked(g, table_name)) for label, g in groups if table_name in g]
        if not tables:
            parts.append(f"<p class=note>plot {html.escape(name)}: its table "
                         f"{html.escape(table_name)} is not in the results</p>")
            continue
        svg = plot_svg(plt, declared, tables, f"{producer}/{name}", paper)
        if svg is None:
            parts.append(f"<p class=note>plot {html.escape(name)}: no point to draw (none finite"
                         ", or none positive on its log axis)</p>")
            continue
        parts.append(f"<figure id=\"plot-{html.escape(name)}\">{svg}"
                     f"<figcaption>{html.escape(name)}</figcaption></figure>")
    return "".join(parts)
