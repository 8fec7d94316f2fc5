"""A plain-SVG x-y chart for the scripts beside it (no plotting library on a bare machine):
frame, tick labels, axis labels, a legend column, linear or log10 axes."""
import math

COLOURS = ["#c0392b", "#2471a3", "#229954", "#b9770e", "#7d3c98", "#566573"]


class Chart:
    W, H, MARGIN, LEGEND = 900, 460, 70, 240

    def __init__(self, xlabel, ylabel, x_range, y_range, log=False):
        self.log = log
        self.x0, self.x1 = x_range
        self.y0, self.y1 = y_range
        self.right = self.W - self.MARGIN - self.LEGEND
        self.legend_rows = 0
        m, h = self.MARGIN, self.H
        self.out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{self.W}" height="{h}" font-family="sans-serif" font-size="12">',
                    f'<rect x="{m}" y="{m}" width="{self.right - m}" height="{h - 2 * m}" fill="none" stroke="black"/>',
                    f'<text x="{(m + self.right) / 2}" y="{h - 20}" text-anchor="middle">{xlabel}</text>',
                    f'<text x="18" y="{h / 2}" text-anchor="middle" transform="rotate(-90 18 {h / 2})">{ylabel}</text>']
        if log:  # ranges are decades: a tick at every power of ten
            xticks = [(10.0**e, f"1e{e}") for e in range(self.x0, self.x1 + 1)]
            yticks = [(10.0**e, f"1e{e}") for e in range(self.y0, self.y1 + 1)]
        else:
            xticks = [(v, f"{v:.3g}") for v in (self.x0 + k * (self.x1 - self.x0) / 5 for k in range(6))]
            yticks = [(v, f"{v:.4g}") for v in (self.y0 + k * (self.y1 - self.y0) / 5 for k in range(6))]
        for v, label in xticks:
            self.out.append(f'<text x="{self.sx(v):.1f}" y="{h - m + 18}" text-anchor="middle">{label}</text>')
        for v, label in yticks:
            self.out.append(f'<text x="{m - 8}" y="{self.sy(v) + 4:.1f}" text-anchor="end">{label}</text>')

    def _t(self, v):
        return math.log10(v) if self.log else v

    def sx(self, v):
        return self.MARGIN + (self._t(v) - self.x0) / (self.x1 - self.x0) * (self.right - self.MARGIN)

    def sy(self, v):
        return self.H - self.MARGIN - (self._t(v) - self.y0) / (self.y1 - self.y0) * (self.H - 2 * self.MARGIN)

    def add(self, element):
        self.out.append(element)

    def polyline(self, points, colour):
        if len(points) > 1:
            self.add('<polyline fill="none" stroke="%s" points="%s"/>'
                     % (colour, " ".join(f"{self.sx(x):.1f},{self.sy(y):.1f}" for x, y in points)))

    def legend(self, text, colour="black"):
        y = self.MARGIN + 10 + 16 * self.legend_rows
        self.add(f'<text x="{self.right + 15}" y="{y}" fill="{colour}" font-size="11">{text}</text>')
        self.legend_rows += 1

    def save(self, path):
        with open(path, "w") as f:
            f.write("\n".join(self.out + ["</svg>"]) + "\n")
