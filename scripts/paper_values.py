"""The paper's values a pipeline declares for report.html ("report": {"paper": [...]}), drawn
over the plot they belong to: black open squares, with error bars where the paper gives them.
A declared plot this run did not make is said so on the page, never dropped in silence."""
import html


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
