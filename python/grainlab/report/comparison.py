"""Comparing direct shear runs: F/N and cap displacement overlaid (paper Fig. 10a, b), peak
friction and dilation angles against mean roundness (Fig. 10c, d) and a table of peaks."""

import html
import os
from pathlib import Path

from .html_page import esc, fmt
from .plotting import Figure, pct_axis, plt, run_colors
from .reading import Run, get, num


def fig_overlay(runs, out_dir):
    """Fig. 10a, b for several runs: F/N and cap displacement against strain, one curve per run."""
    f = Figure("Stress ratio and cap displacement of all runs", "Fig. 10a, b",
               "Top: stress ratio F/N against shear strain; bottom: vertical displacement of the top cap (up = "
               "dilation) against shear strain; one curve per run, labelled by its grain class "
               "(config.grains.preset).")
    col = run_colors(runs)
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 7.4), sharex=True)
    for r in runs:
        ratio, dv = r.col("stress_ratio"), r.col("vertical_displacement_m")
        if ratio is not None:
            a1.plot(r.strain_pct, ratio, color=col[id(r)], lw=1.5, label=r.label)
        else:
            f.missing(f"{r.name}/series.csv column stress_ratio")
        if dv is not None:
            a2.plot(r.strain_pct, 1e3 * dv, color=col[id(r)], lw=1.5, label=r.label)
        else:
            f.missing(f"{r.name}/series.csv column vertical_displacement_m")
    a1.set_ylabel("stress ratio F/N (–)")
    a1.set_ylim(bottom=0)
    a1.set_title("(a) stress ratio")
    a1.legend(title="grain class", loc="lower right")
    a2.axhline(0, color="0.3", lw=0.8)
    a2.set_ylabel("cap vertical displacement $d_v$ (mm), up = dilation")
    a2.set_title("(b) cap vertical displacement")
    pct_axis(a2)
    fig.tight_layout()
    return f.save(fig, out_dir, "stress_strain_overlay.png")


def fig_peaks_vs_roundness(runs, out_dir):
    """Fig. 10c, d: peak friction and dilation angles against mean grain roundness."""
    f = Figure("Peak friction and dilation angles against mean roundness", "Fig. 10c, d",
               "Peak friction angle &phi;<sub>p</sub> (left) and peak dilation angle &psi;<sub>p</sub> (right) of "
               "each run against the mean Wadell roundness R of its grains (run.json mean_roundness). An open "
               "marker is a run whose largest value lies in the last 5 % of its strain: no peak reached.")
    have = [r for r in runs if num(r.info.get("mean_roundness")) is not None]
    lacking = [r.name for r in runs if r not in have]
    if not have:
        return f.missing("run.json mean_roundness", "in every run")
    if lacking:
        f.missing("run.json mean_roundness", "in " + ", ".join(lacking) + ", left out of the plot")
    col = run_colors(runs)
    fig, axes = plt.subplots(1, 2, figsize=(10.0, 4.2))
    for ax, peak, ylabel, title in ((axes[0], Run.peak_friction, "peak friction angle $\\phi_p$ (deg)", "(c)"),
                                    (axes[1], Run.peak_dilation, "peak dilation angle $\\psi_p$ (deg)", "(d)")):
        for r in have:
            v, _, is_peak = peak(r)
            if v is None:
                continue
            R = float(r.info["mean_roundness"])
            ax.plot([R], [v], "o", ms=8, color=col[id(r)], mfc=col[id(r)] if is_peak else "none")
            ax.annotate(r.label, (R, v), xytext=(6, 5), textcoords="offset points", fontsize=8)
        ax.set_xlabel("mean grain roundness R (–)")
        ax.set_ylabel(ylabel)
        ax.set_title(f"{title} {ylabel.split(' $')[0]}")
        ax.margins(x=0.15, y=0.2)
    fig.tight_layout()
    return f.save(fig, out_dir, "peaks_vs_roundness.png")


def comparison_table(runs, out_dir):
    head = ["run", "grain class", "sand preset", "grains", "mean roundness R",
            "e after preparation, whole / bulk", "D<sub>r</sub> (%)",
            "&phi;<sub>p</sub> (deg)", "&epsilon;<sub>s</sub> at &phi;<sub>p</sub> (%)", "&psi;<sub>p</sub> (deg)",
            "&Psi;<sub>p</sub> all / band", "final &phi; (deg)", "final e", "wall time (h)"]
    rows = []
    for r in runs:
        phi_p, e_phi, phi_is_peak = r.peak_friction()
        psi_p, _, _ = r.peak_dilation()
        dr = num(get(r.info, "preparation", "relative_density"))
        report = r.dir / "report" / "index.html"
        name = esc(r.name)
        if report.is_file():
            name = f'<a href="{html.escape(Path(os.path.relpath(report, out_dir)).as_posix())}">{name}</a>'
        wall = num(get(r.info, "timings", "wall_s"))
        rows.append([name, esc(r.preset), esc(r.sand), esc(get(r.info, "grains")), fmt(get(r.info, "mean_roundness"), ".3f"),
                     f'{fmt(get(r.info, "preparation", "void_ratio"), ".4f")} / '
                     f'{fmt(get(r.info, "preparation", "bulk_void_ratio"), ".4f")}',
                     fmt(None if dr is None else 100 * dr, ".1f"),
                     fmt(phi_p, ".2f"),
                     fmt(None if e_phi is None else 100 * e_phi, ".2f") + ("" if phi_is_peak else " (the end: no peak)"),
                     fmt(psi_p, ".2f"),
                     f"{fmt(r.peak_psi(), '.3f')} / {fmt(r.peak_psi(band=True), '.3f')}",
                     fmt(get(r.info, "final", "friction_angle_deg"), ".2f"), fmt(get(r.info, "final", "void_ratio"), ".4f"),
                     fmt(None if wall is None else wall / 3600, ".2f")])
    th = "".join(f"<th>{h}</th>" for h in head)
    body = "\n".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows)
    return (f'<table class="grid"><caption>Peaks and preparation of each run (a run\'s name links to its own '
            f'report when it has one)</caption>\n<tr>{th}</tr>\n{body}\n</table>')
