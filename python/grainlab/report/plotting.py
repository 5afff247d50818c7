"""The figures' common parts: matplotlib (Agg backend, the report's style), colours, the
Figure record (a PNG with its caption and notes) and the shared 'all grains and shear band
against strain' figure."""

import matplotlib

matplotlib.use("Agg")  # no display: PNGs only
import matplotlib.pyplot as plt  # noqa: E402

DPI = 130
ALL_COLOR, BAND_COLOR = "#1f4e9c", "#c0392b"
RUN_COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
              "#7f7f7f", "#bcbd22"]

plt.rcParams.update({
    "font.size": 10, "axes.titlesize": 11, "axes.labelsize": 10, "legend.fontsize": 9,
    "axes.grid": True, "grid.alpha": 0.3, "savefig.bbox": "tight", "savefig.dpi": DPI,
})


# ---------------------------------------------------------------------------
# Figure records.

class Figure:
    """One entry of the report: a PNG (or none) with its caption and notes."""

    def __init__(self, title, paper, caption=""):
        self.title, self.paper, self.caption = title, paper, caption
        self.png = None
        self.notes = []      # "not available: ..." and partial-data notes
        self.warnings = []   # consistency problems found in the data

    def missing(self, what, detail=""):
        self.notes.append(f"not available: {what} missing" + (f" ({detail})" if detail else ""))
        return self

    def save(self, fig, out_dir, name):
        fig.savefig(out_dir / name)
        plt.close(fig)
        self.png = name
        return self


def pct_axis(ax):
    ax.set_xlabel("shear strain $\\varepsilon_s = d_h / L$ (%)")
    ax.set_xlim(left=0)


def all_band_figure(run, out_dir, name, cols, ylabel, title, paper, caption):
    """Shared body of the 'all grains and shear band against strain' figures (13, 14, 16)."""
    f = Figure(title, paper, caption)
    c_all, c_band = run.col(cols[0]), run.col(cols[1])
    if c_all is None and c_band is None:
        return f.missing(f"series.csv columns {cols[0]} and {cols[1]}")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    x = run.strain_pct
    if c_all is not None:
        ax.plot(x, c_all, color=ALL_COLOR, lw=1.6, label="all grains")
    else:
        f.missing(f"series.csv column {cols[0]} (all grains)")
    if c_band is not None:
        ax.plot(x, c_band, color=BAND_COLOR, lw=1.6, ls="--", label="grains in the shear band")
    else:
        f.missing(f"series.csv column {cols[1]} (shear band)")
    pct_axis(ax)
    ax.set_ylabel(ylabel)
    ax.legend(loc="best")
    ax.set_title(title)
    return f.save(fig, out_dir, name)


# ---------------------------------------------------------------------------
# Comparisons: one colour per run.

def run_colors(runs):
    return {id(r): RUN_COLORS[k % len(RUN_COLORS)] for k, r in enumerate(runs)}
