"""The four-sand study report (bench/study_four_sands.cpp): one HTML page comparing the sands.

Usage:  python3 -m grainlab.report.study STUDY_DIR [--out DIR]   # -> STUDY_DIR/report/index.html

STUDY_DIR holds study.json (written by study_four_sands: per sand its own
index void ratios e_min/e_max, the deposition friction found for Dr 0.9 and
the run folder; the damping runs) and the run folders (series.csv, run.json,
as `grainlab run` writes them). Like the run report (whose reading code and
figures it shares) it derives no physics: it picks values from the engine's
files (a peak's row, the row at 10 % strain) and draws them.

Figures (He, Zheng & Schaefer 2021):
  Fig. 10a-d  F/N and cap displacement of the four sands; phi_p, psi_p against roundness
  Fig. 13b    mean grain rotation at 10 % strain against roundness
  Fig. 14b    coordination number at 10 % strain against roundness
  Fig. 16b    peak fabric factor Psi_p against roundness
  Fig. 18a, b glass beads under the three damping sets (Appendix 2), with the spread
              of the peak stress ratio and of the final cap displacement
  Fig. 19     angular grains to 20 % strain (Appendix 3), with the change of F/N and
              of the cap displacement between 15 and 20 % strain
and a table per run: roundness, e_min, e_max, e, Dr, phi_p, psi_p, strain at
peak, mean rotation, final CN, Psi_p, wall time. Each of the paper's trends is
stated as holding or not, with the numbers.

A sand run with several seeds (study_four_sands --seeds N: other grain shapes
of the same class, another fill) is one point per run in the figures and a
row per run plus a row of means in the table; a trend is judged on the
sands' means, and where two sands' ranges over their seeds overlap it says
so: the trend between them is not resolved by the specimens at hand.
"""

import argparse
import html
import json
import sys
from collections import OrderedDict
from pathlib import Path

import numpy as np

from .comparison import fig_overlay, fig_peaks_vs_roundness
from .html_page import COMPARISON_PNGS, esc, figure_html, fmt, prepare_out, write_page
from .plotting import ALL_COLOR, BAND_COLOR, RUN_COLORS, Figure, pct_axis, plt
from .reading import ReportError, Run, get, num

STUDY_PNGS = COMPARISON_PNGS + ["micro_vs_roundness.png", "damping.png", "angular_20.png"]
AT_STRAIN = 0.10  # the comparisons' strain (the paper's final strain; a shorter run: its end)
FIRST_SEED = 7  # study_four_sands' first seed (a run folder named after the sand alone)


def value_at(run, column, strain=AT_STRAIN):
    """The column's value at the last sample at or below `strain`, or None."""
    c = run.col(column)
    if c is None:
        return None
    s = run.series["shear_strain"]
    k = np.nonzero(s <= strain + 1e-9)[0]
    return None if len(k) == 0 else num(c[k[-1]])


class Sand:
    def __init__(self, study_dir, entry):
        self.entry = entry
        self.run = Run(study_dir / entry["run_folder"])
        self.name = entry["name"]
        self.seed = int(entry.get("seed", FIRST_SEED))
        self.run.label = self.name if self.seed == FIRST_SEED else f"{self.name} seed {self.seed}"
        self.R = num(self.run.info.get("mean_roundness"))
        self.phi_p, self.strain_at_peak, _ = self.run.peak_friction()
        self.psi_p, _, _ = self.run.peak_dilation()
        self.rotation = value_at(self.run, "rotation_mean_deg")
        self.cn = value_at(self.run, "coordination_number")
        self.psi_fabric = self.run.peak_psi()
        # A Dr on the own indices is judged on the bulk void ratio, as the indices are.
        prep = self.run.info.get("preparation", {})
        self.e = num(prep.get("bulk_void_ratio") if "own_e_min" in prep else prep.get("void_ratio"))
        self.dr = num(get(self.run.info, "preparation", "relative_density"))
        self.wall = (num(entry.get("preparation_wall_s")) or 0) + (num(entry.get("run_wall_s")) or 0)


class Group:
    """The runs of one sand (one per seed): means and ranges of what the trends compare."""

    ATTRS = ("R", "phi_p", "psi_p", "psi_fabric", "rotation", "cn")

    def __init__(self, name, runs):
        self.name, self.runs = name, runs
        for attr in self.ATTRS:
            v = [getattr(r, attr) for r in runs if getattr(r, attr) is not None]
            setattr(self, attr, float(np.mean(v)) if v else None)
            setattr(self, attr + "_range", (min(v), max(v)) if v else None)


def groups_of(sands):
    by_name = OrderedDict()
    for s in sands:
        by_name.setdefault(s.name, []).append(s)
    return [Group(name, runs) for name, runs in by_name.items()]


def trend(groups, attr, falling, what):
    """'holds' or 'does not hold' for a strict trend of the sands' means of attr with roundness,
    with the numbers; with several seeds, whether neighbouring sands' ranges overlap."""
    have = sorted([g for g in groups if g.R is not None and getattr(g, attr) is not None], key=lambda g: g.R)
    vals = [getattr(g, attr) for g in have]
    ok = len(vals) >= 2 and all((b < a) if falling else (b > a) for a, b in zip(vals, vals[1:]))

    def number(g):
        lo, hi = getattr(g, attr + "_range")
        seeds = f" [{lo:.3g} to {hi:.3g}, {len(g.runs)} seeds]" if len(g.runs) > 1 else ""
        return f"{g.name} (R {g.R:.2f}) {getattr(g, attr):.3g}{seeds}"

    numbers = ", ".join(number(g) for g in have)
    verdict = "holds" if ok else "DOES NOT HOLD" if len(vals) >= 2 else "cannot tell (fewer than two sands)"
    overlaps = [f"{a.name}/{b.name}" for a, b in zip(have, have[1:])
                if (len(a.runs) > 1 or len(b.runs) > 1)
                and min(getattr(a, attr + "_range")[1], getattr(b, attr + "_range")[1])
                >= max(getattr(a, attr + "_range")[0], getattr(b, attr + "_range")[0])]
    unresolved = f"; the seeds' ranges overlap for {', '.join(overlaps)}: not resolved there" if overlaps else ""
    mean = " (means over seeds)" if any(len(g.runs) > 1 for g in have) else ""
    return (f"{what} {'falls' if falling else 'rises'} strictly with roundness{mean}: {verdict}{unresolved} "
            f"({numbers})", ok)


def fig_micro(sands, groups, out_dir):
    f = Figure("Mean rotation, coordination number and peak fabric factor against roundness", "Figs. 13b, 14b, 16b",
                  "Left: mean grain rotation at 10 % strain (series.csv rotation_mean_deg); middle: coordination "
                  "number at 10 % strain; right: the largest fabric factor &Psi; during shear (run.json "
                  "peaks.fabric_psi); each against the mean Wadell roundness of the sand's grains. With several "
                  "seeds a sand, the points are the runs and the line joins the sands' means.")
    fig, axes = plt.subplots(1, 3, figsize=(13.0, 4.0))
    for ax, attr, ylabel, title in ((axes[0], "rotation", "mean rotation at 10 % (deg)", "(13b) rotation"),
                                    (axes[1], "cn", "coordination number at 10 % (–)", "(14b) final CN"),
                                    (axes[2], "psi_fabric", "peak fabric factor $\\Psi_p$ (–)", "(16b) $\\Psi_p$")):
        pts = [(s.R, getattr(s, attr), s.run.label) for s in sands if s.R is not None and getattr(s, attr) is not None]
        if not pts:
            f.missing(f"{attr} of every sand")
            continue
        means = sorted((g.R, getattr(g, attr)) for g in groups if g.R is not None and getattr(g, attr) is not None)
        ax.plot([m[0] for m in means], [m[1] for m in means], "-", color=ALL_COLOR)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", color=ALL_COLOR, ms=7)
        for R, v, name in pts:
            ax.annotate(name, (R, v), xytext=(5, 4), textcoords="offset points", fontsize=8)
        ax.set_xlabel("mean grain roundness R (–)")
        ax.set_ylabel(ylabel)
        ax.set_title(title)
        ax.margins(x=0.15, y=0.2)
    fig.tight_layout()
    return f.save(fig, out_dir, "micro_vs_roundness.png")


def fig_damping(runs, out_dir, notes):
    f = Figure("Glass beads under three damping sets", "Appendix 2, Fig. 18a, b",
                  "Stress ratio (top) and cap displacement (bottom) of glass beads with the user Hertz law and "
                  "(&gamma;<sub>n</sub>, &gamma;<sub>t</sub>) = (20, 10), (40, 20), (80, 40).")
    if not runs:
        return f.missing("damping runs")
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 7.0), sharex=True)
    for k, r in enumerate(runs):
        c = RUN_COLORS[k % len(RUN_COLORS)]
        a1.plot(r.strain_pct, r.col("stress_ratio"), color=c, lw=1.4, label=r.label)
        a2.plot(r.strain_pct, 1e3 * r.col("vertical_displacement_m"), color=c, lw=1.4, label=r.label)
    a1.set_ylabel("stress ratio F/N (–)")
    a1.legend(loc="lower right")
    a2.set_ylabel("cap displacement $d_v$ (mm)")
    pct_axis(a2)
    fig.tight_layout()
    for n in notes:
        f.notes.append(n)
    return f.save(fig, out_dir, "damping.png")


def fig_angular(sand, out_dir, notes):
    f = Figure("Angular grains to 20 % strain", "Appendix 3, Fig. 19",
                  "Stress ratio and cap displacement of the angular grains to 20 % strain; the shaded band is 15-20 %.")
    if sand is None:
        return f.missing("the angular run")
    r = sand.run
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 6.5), sharex=True)
    a1.plot(r.strain_pct, r.col("stress_ratio"), color=ALL_COLOR)
    a2.plot(r.strain_pct, 1e3 * r.col("vertical_displacement_m"), color=BAND_COLOR)
    for a in (a1, a2):
        a.axvspan(15, 20, color="0.9")
    a1.set_ylabel("stress ratio F/N (–)")
    a2.set_ylabel("cap displacement $d_v$ (mm)")
    pct_axis(a2)
    fig.tight_layout()
    for n in notes:
        f.notes.append(n)
    return f.save(fig, out_dir, "angular_20.png")


def spread_pct(values):
    v = [x for x in values if x is not None]
    if len(v) < 2:
        return None
    return 100 * (max(v) - min(v)) / abs(np.mean(v))


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python3 -m grainlab.report.study",
                                 description="Comparison report of the four-sand study (bench/study_four_sands).")
    ap.add_argument("study", help="the study folder (study.json and the run folders)")
    ap.add_argument("--out", help="output folder (default STUDY/report)")
    a = ap.parse_args(argv)
    study_dir = Path(a.study)
    try:
        study = json.loads((study_dir / "study.json").read_text())
    except (OSError, ValueError) as e:
        print(f"grainlab.report.study: error: cannot read {study_dir / 'study.json'}: {e}", file=sys.stderr)
        return 1
    out_dir = Path(a.out) if a.out else study_dir / "report"
    try:
        finished = lambda e: "run_folder" in e and (study_dir / e["run_folder"] / "run.json").is_file()  # noqa: E731
        sands = [Sand(study_dir, s) for s in study.get("sands", []) if finished(s)]
        unfinished = [s.get("name", "?") for s in study.get("sands", []) if not finished(s)]
        damping = []
        for d in study.get("damping", []):
            if "run_folder" in d and (study_dir / d["run_folder"] / "run.json").is_file():
                r = Run(study_dir / d["run_folder"])
                r.label = f"γn {d['gamma_n']:g}, γt {d['gamma_t']:g}"
                damping.append(r)
    except ReportError as e:
        print(f"grainlab.report.study: error: {e}", file=sys.stderr)
        return 1
    if not sands:
        print("grainlab.report.study: error: study.json lists no finished sand run", file=sys.stderr)
        return 1
    prepare_out(out_dir, STUDY_PNGS)

    groups = groups_of(sands)
    checks = [f"no finished run for: {', '.join(unfinished)}"] if unfinished else []
    for attr, falling, what in (("phi_p", True, "peak friction angle"), ("psi_p", True, "peak dilation angle"),
                                ("psi_fabric", True, "peak fabric factor Psi_p"),
                                ("rotation", False, "mean rotation at 10 %"), ("cn", False, "coordination number at 10 %")):
        checks.append(trend(groups, attr, falling, what)[0])

    damping_notes = []
    if damping:
        peaks = [num(get(r.info, "peaks", "stress_ratio")) for r in damping]
        finals = [num(r.col("vertical_displacement_m")[-1]) for r in damping]
        sp, sf = spread_pct(peaks), spread_pct(finals)
        damping_notes.append(f"peak F/N: {', '.join(f'{p:.4f}' for p in peaks if p is not None)}; spread "
                             f"{sp:.2f} % of the mean ({'within' if sp is not None and sp <= 2 else 'ABOVE'} the paper's 2 %)")
        damping_notes.append(f"final cap displacement (mm): {', '.join(f'{1e3 * v:.4f}' for v in finals if v is not None)}; "
                             f"spread {sf:.2f} % of the mean ({'within' if sf is not None and sf <= 5 else 'ABOVE'} the paper's 5 %)")
        checks += damping_notes
    angular = next((s for s in sands if s.name == "angular" and s.seed == FIRST_SEED), None)
    angular_notes = []
    if angular is not None and float(angular.run.series["shear_strain"][-1]) >= 0.199:
        r = angular.run
        at15 = lambda c: value_at(r, c, 0.15)  # noqa: E731
        at20 = lambda c: value_at(r, c, 0.20)  # noqa: E731
        d_ratio = at20("stress_ratio") - at15("stress_ratio")
        d_dv = at20("vertical_displacement_m") - at15("vertical_displacement_m")
        d_dv_early = at15("vertical_displacement_m") - value_at(r, "vertical_displacement_m", 0.10)
        angular_notes.append(f"F/N changes by {d_ratio:+.4f} between 15 and 20 % strain "
                             f"(peak {angular.run.peak_friction()[0]:.1f} deg)")
        angular_notes.append(f"cap displacement changes by {1e3 * d_dv:+.4f} mm between 15 and 20 % "
                             f"(by {1e3 * d_dv_early:+.4f} mm between 10 and 15 %)")
        checks += angular_notes

    figs = [fig_overlay([s.run for s in sands], out_dir), fig_peaks_vs_roundness([s.run for s in sands], out_dir),
            fig_micro(sands, groups, out_dir), fig_damping(damping, out_dir, damping_notes),
            fig_angular(angular, out_dir, angular_notes)]

    head = ["sand", "grain class", "roundness R", "e<sub>min</sub>", "e<sub>max</sub>", "e", "D<sub>r</sub> (%)",
            "&phi;<sub>p</sub> (deg)", "&psi;<sub>p</sub> (deg)", "&epsilon;<sub>s</sub> at &phi;<sub>p</sub> (%)",
            "mean rotation at 10 % (deg)", "CN at 10 %", "&Psi;<sub>p</sub>", "wall time (h)"]
    rows = []
    for g in groups:
        for s in g.runs:
            rows.append([esc(s.run.label), esc(s.run.preset), fmt(s.R, ".3f"), fmt(s.entry.get("e_min"), ".4f"),
                         fmt(s.entry.get("e_max"), ".4f"), fmt(s.e, ".4f"),
                         fmt(None if s.dr is None else 100 * s.dr, ".1f"), fmt(s.phi_p, ".2f"),
                         fmt(s.psi_p, ".2f"),
                         fmt(None if s.strain_at_peak is None else 100 * s.strain_at_peak, ".2f"),
                         fmt(s.rotation, ".2f"), fmt(s.cn, ".3f"), fmt(s.psi_fabric, ".3f"),
                         fmt(s.wall / 3600, ".2f")])
        if len(g.runs) > 1:
            rows.append([f"<b>{esc(g.name)}: mean of {len(g.runs)} seeds</b>", "", fmt(g.R, ".3f"), "", "", "", "",
                         fmt(g.phi_p, ".2f"), fmt(g.psi_p, ".2f"), "", fmt(g.rotation, ".2f"),
                         fmt(g.cn, ".3f"), fmt(g.psi_fabric, ".3f"), ""])
    th = "".join(f"<th>{h}</th>" for h in head)
    body = "\n".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows)
    table = (f'<table class="grid"><caption>Per run (e<sub>min</sub>, e<sub>max</sub>: the sand\'s own index void '
             f'ratios measured by the study; D<sub>r</sub> on them)</caption>\n<tr>{th}</tr>\n{body}\n</table>')
    checks_html = "<ul>" + "".join(f"<li>{html.escape(c)}</li>" for c in checks) + "</ul>"
    subtitle = (f"{len(groups)} sands, {len(sands)} runs{' (QUICK mode: tiny box, few faces; not the study)' if study.get('quick') else ''}, "
                f"target D<sub>r</sub> {study.get('target_relative_density')}, {study.get('threads')} threads.")
    blocks = ["<h2>Table</h2>", table, "<h2>The paper's trends, measured</h2>", checks_html, "<h2>Figures</h2>"]
    blocks += [figure_html(f) for f in figs]
    page = write_page(out_dir, "grainlab four-sand study", subtitle, blocks)
    print(f"report: {page.resolve()}")
    for c in checks:
        print(f"  {c}")
    for f in figs:
        for n in f.notes:
            if n.startswith("not available"):
                print(f"  {f.paper}: {n}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
