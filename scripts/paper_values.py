"""The paper's values a pipeline declares for report.html ("report": {"paper": [...]}), drawn
over the plot they belong to: black open squares, with error bars where the paper gives them.
A declared plot this run did not make is said so on the page, never dropped in silence."""
import html
import numbers


def is_number_list(value):
    return isinstance(value, list) and all(isinstance(v, numbers.Real) and not isinstance(v, bool)
                                           for v in value)


def paper_problem(entries):
    """What is wrong with the "report": {"paper": [...]} entries, as "where: expected ...,
    found ...", or "" when each is an object of a plot, a label, and x, y (and y_err) lists of
    numbers of one length."""
    if not isinstance(entries, list):
        return f"report.paper: expected a list of paper values, found {type(entries).__name__}"
    for k, entry in enumerate(entries):
        where = f"report.paper[{k}]"
        if not isinstance(entry, dict):
            return f"{where}: expected an object, found {type(entry).__name__}"
        for key in ("plot", "label"):
            if not isinstance(entry.get(key), str):
                return f"{where}.{key}: expected a string, found {entry.get(key)!r}"
        lists = [key for key in ("x", "y", "y_err") if key in entry or key != "y_err"]
        for key in lists:
            if not is_number_list(entry.get(key)):
                return f"{where}.{key}: expected a list of numbers, found {entry.get(key)!r}"
        lengths = [len(entry[key]) for key in lists]
        if len(set(lengths)) > 1:
            return (f"{where}: expected {', '.join(lists)} of one length, found lengths "
                    f"{', '.join(map(str, lengths))}")
    return ""


class PaperValues:
    def __init__(self, pipeline):
        self.by_plot = {}
        for entry in pipeline.get("report", {}).get("paper", []):
            self.by_plot.setdefault(entry["plot"], []).append(entry)
        self.drawn = set()

    def of(self, plot):
        """The entries for `plot` ("producer/name"), which count as drawn from now on."""
        if plot in self.by_plot:
            self.drawn.add(plot)
        return self.by_plot.get(plot, [])

    def draw(self, ax, plot, keep):
        """Draws the entries of `plot` on `ax`; keep(x, y, e) -> the drawable points."""
        import numpy as np
        for entry in self.of(plot):
            e = np.array(entry["y_err"], float) if "y_err" in entry else None
            x, y, e = keep(np.array(entry["x"], float), np.array(entry["y"], float), e)
            ax.errorbar(x, y, yerr=e, fmt="s", color="black", mfc="none", capsize=2,
                        label=entry["label"], zorder=3)

    def notes(self):
        """A note for every entry whose plot this run did not draw."""
        return "".join(f"<p class=note>paper values \"{html.escape(e['label'])}\" for the plot "
                       f"{html.escape(plot)}: this run has no such plot</p>"
                       for plot, entries in self.by_plot.items() if plot not in self.drawn
                       for e in entries)
