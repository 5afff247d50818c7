"""Which report a set of run folders gets (direct shear, oedometer, triaxial, any other test;
a comparison of direct shear or of triaxial runs), and the direct shear pages themselves."""

import html
import re
from pathlib import Path

import numpy as np

from .comparison import comparison_table, fig_overlay, fig_peaks_vs_roundness
from .curves import fig_coordination, fig_rotation, fig_stress_ratio
from .dilation import fig_vertical_displacement
from .fabric import fig_fabric_psi, fig_rose
from .force_chains import fig_force_chains
from .generic import generic_report
from .html_page import COMPARISON_OUTPUTS, SINGLE_PNGS, esc, figure_html, prepare_out, table_html, write_page
from .oedometer import oedometer_report
from .profile import fig_displacement_profile
from .reading import PROGRESS_COLUMNS, ReportError, Run, get
from .tables import inputs_rows, results_rows
from .triaxial import triaxial_report
from .triaxial_comparison import triaxial_comparison_report


def single_report(run, out_dir):
    if run.test == "oedometer":
        return oedometer_report(run, out_dir)
    if run.test == "triaxial":
        return triaxial_report(run, out_dir)
    if run.test not in PROGRESS_COLUMNS:
        return generic_report(run, out_dir)
    prepare_out(out_dir, SINGLE_PNGS)
    figs = [fn(run, out_dir) for fn in (fig_stress_ratio, fig_vertical_displacement, fig_displacement_profile,
                                        fig_rotation, fig_coordination, fig_rose, fig_fabric_psi, fig_force_chains)]
    subtitle = (f"Direct shear run <code>{html.escape(run.name)}</code> (folder <code>{html.escape(str(run.dir.resolve()))}"
                f"</code>): grain class "
                f"{esc(run.preset)}, sand preset {esc(run.sand)}, {esc(get(run.info, 'grains'))} grains.")
    toc = "<ul>" + "".join(f'<li><a href="#{html.escape(Path(f.png).stem)}">{html.escape(f.title)}</a> ({f.paper})</li>'
                           if f.png else f"<li>{html.escape(f.title)} ({f.paper}): not available</li>" for f in figs) + "</ul>"
    blocks = ['<h2>Inputs and results</h2>\n<div class="tables">',
              table_html(inputs_rows(run), "Inputs (run.json)"),
              table_html(results_rows(run), "Peaks and results"), "</div>",
              "<h2>Figures</h2>", toc]
    blocks += [figure_html(f) for f in figs]
    return write_page(out_dir, f"grainlab run report: {run.name}", subtitle, blocks), figs


def comparison_report(runs, out_dir):
    tests = {r.test for r in runs}
    if tests == {"triaxial"}:
        return triaxial_comparison_report(runs, out_dir)
    if tests != {"direct-shear"}:
        raise ReportError("a comparison report compares runs of one test, all direct-shear or all triaxial "
                          "(oedometer comparisons are not built); these are " +
                          ", ".join(f"{r.name}: {r.test}" for r in runs) + ": report them separately")
    prepare_out(out_dir, COMPARISON_OUTPUTS)
    figs = [fig_overlay(runs, out_dir), fig_peaks_vs_roundness(runs, out_dir)]
    subtitle = f"{len(runs)} direct shear runs: " + ", ".join(
        f"<code>{html.escape(r.name)}</code> ({esc(r.preset)})" for r in runs) + "."
    blocks = ["<h2>Peaks</h2>", comparison_table(runs, out_dir), "<h2>Figures</h2>"]
    blocks += [figure_html(f) for f in figs]
    return write_page(out_dir, "grainlab comparison report", subtitle, blocks), figs


def disambiguate_labels(runs):
    seen = {}
    for r in runs:
        seen.setdefault(r.label, []).append(r)
    for label, group in seen.items():
        if len(group) > 1:
            for r in group:
                r.label = f"{label} ({r.name})"


def write_report(folders, out=None):
    """The report of one run folder, or the comparison of several: (path of index.html, the Figure records).
    Written to `out`, else RUN_DIR/report for one run and RUN_DIR/../comparison/report for several (after the
    first). Raises ReportError when a folder is not a run folder or the runs cannot be compared."""
    runs = [Run(d) for d in folders]
    disambiguate_labels(runs)
    if out:
        out_dir = Path(out)
    elif len(runs) == 1:
        out_dir = runs[0].dir / "report"
    else:
        out_dir = runs[0].dir.resolve().parent / "comparison" / "report"
    with np.errstate(invalid="ignore", divide="ignore"):
        if len(runs) == 1:
            return single_report(runs[0], out_dir)
        return comparison_report(runs, out_dir)


def summary_lines(page, figs):
    """What the command line prints once the report is written: its path, the figures, their notes."""
    written = [f.png for f in figs if f.png]
    lines = [f"report: {page.resolve()}",
             f"figures written ({len(written)}): " + (", ".join(written) if written else "none")]
    for f in figs:
        lines += [f"  {f.paper}: {n}" for n in f.notes]
        lines += [f"  {f.paper}: warning: {html.unescape(re.sub('<[^>]+>', '', w))}" for w in f.warnings]
    return lines
