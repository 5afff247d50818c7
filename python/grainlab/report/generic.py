"""The report of a lab test with no figures of its own: every series column against the
test's progress column, and run.json's group of the test."""

import html

from .html_page import SINGLE_PNGS, esc, figure_html, fmt, fmt_duration, prepare_out, table_html, write_page
from .plotting import ALL_COLOR, Figure, plt
from .reading import get, num
from .tables import inputs_rows, preparation_rows


# ---------------------------------------------------------------------------
# A lab test this report has no figures of: every series column against the
# test's progress column, and run.json's numbers of the test's own group.

def fig_series(run, out_dir):
    x_name = run.progress_column
    cols = [c for c in run.series if c not in (x_name, "time_s") and run.col(c) is not None]
    f = Figure(f"Every series column against {x_name}", "series.csv",
               f"Each column of series.csv that has a number against the test's progress column {html.escape(x_name)}, "
               "in the engine's units (SI; the column names carry them).")
    if not cols:
        return f.missing(f"series.csv columns besides {x_name} and time_s")
    ncols = min(3, len(cols))
    nrows = (len(cols) + ncols - 1) // ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(4.2 * ncols, 2.8 * nrows), squeeze=False, sharex=True)
    for ax, c in zip(axes.flat, cols):
        ax.plot(run.series[x_name], run.series[c], color=ALL_COLOR, lw=1.2)
        ax.set_title(c, fontsize=9)
    for ax in axes.flat[len(cols):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel(x_name)
    fig.tight_layout()
    return f.save(fig, out_dir, "series.png")


def generic_report(run, out_dir):
    prepare_out(out_dir, SINGLE_PNGS)
    figs = [fig_series(run, out_dir)]
    group = get(run.info, run.test, default={})
    own = [(html.escape(k), fmt(v, ".4g")) for k, v in group.items() if num(v) is not None] if isinstance(group, dict) else []
    results = own + preparation_rows(run) + [
        ("wall time", fmt_duration(get(run.info, "timings", "wall_s"))),
        ("rows in series.csv", str(len(run.series[run.progress_column]))),
    ]
    subtitle = (f"{html.escape(run.test)} run <code>{html.escape(run.name)}</code> (folder <code>"
                f"{html.escape(str(run.dir.resolve()))}</code>): grain class {esc(run.preset)}, sand preset "
                f"{esc(run.sand)}, {esc(get(run.info, 'grains'))} grains. This report has no figures of its own "
                f"for the test {html.escape(run.test)}: it draws every series column against {html.escape(run.progress_column)}.")
    blocks = ['<h2>Inputs and results</h2>\n<div class="tables">', table_html(inputs_rows(run), "Inputs (run.json)"),
              table_html(results, f"Results (run.json {html.escape(run.test)} and preparation)"), "</div>",
              "<h2>Figures</h2>"]
    blocks += [figure_html(f) for f in figs]
    return write_page(out_dir, f"grainlab {run.test} report: {run.name}", subtitle, blocks), figs
