"""Comparing triaxial runs at several confining stresses: overlays, stress paths, Mohr circles
and the Mohr-Coulomb envelopes the engine fitted (mohr_coulomb.json)."""

import html
import json
import math

import numpy as np
import matplotlib.transforms

from .html_page import (COMPARISON_PNGS, TRIAXIAL_COMPARISON_PNGS, esc, figure_html, fmt, grid_html, prepare_out,
                        run_link, write_page)
from .plotting import Figure, plt, run_colors
from .reading import get, num


# ---------------------------------------------------------------------------
# Comparing triaxial runs at several confining stresses: overlays, stress
# paths, Mohr circles and the Mohr-Coulomb envelope fitted over the runs.
#
# Each run gives two circles: at the peak and at the critical state. The
# engine computes them and fits the envelopes (src/analysis/mohr_coulomb.h):
# `grainlab report` writes mohr_coulomb.json next to the comparison's page
# (src/io/mohr_coulomb_file.h) before it runs this package, which reads and
# draws it. Run alone (python3 -m grainlab.report) on triaxial runs, it has no
# fit to show and says so.

def triaxial_sigma3(run):
    """sigma_3 of the run (Pa): the cell pressure its sides' servos held, config.consolidation.normal_stress."""
    return num(get(run.info, "config", "consolidation", "normal_stress"))


def tidy(x):
    """x without a minus sign on a value that rounds to zero (a fitted c' of -1e-14 Pa is 0.00 kPa)."""
    return round(x, 9) + 0.0


# What mohr_coulomb.json lacks when the report was run without grainlab report.
MOHR_MISSING = ("mohr_coulomb.json", "grainlab report fits the envelopes and writes it next to the page: "
                "compare the runs with `grainlab report RUN_A RUN_B ...`")

ENVELOPES = (("peak", "peak_stress_ratio", "peak_friction_angle_deg", "peak"),
             ("critical_state", "critical_stress_ratio", "critical_friction_angle_deg", "critical state"))


def read_mohr(runs, out_dir):
    """mohr_coulomb.json of the comparison (grainlab report writes it in out_dir) as, per envelope ('peak',
    'critical_state'): the runs' circles [(run, sigma_1, sigma_3)], the fit (with only 'refused' when the
    engine fitted none) and the runs left out (names); None when the file is missing or unreadable."""
    try:
        doc = json.loads((out_dir / "mohr_coulomb.json").read_text())
    except (OSError, ValueError):
        return None
    if not isinstance(doc, dict):
        return None
    by_folder = {str(r.dir.resolve()): r for r in runs}
    entries = [e for e in doc.get("runs", []) if isinstance(e, dict) and e.get("folder") in by_folder]
    out = {}
    for env, _, _, _ in ENVELOPES:
        circles = [(by_folder[e["folder"]], num(get(e, env, "sigma1_Pa")), num(get(e, env, "sigma3_Pa")))
                   for e in entries if isinstance(e.get(env), dict)]
        circles = [c for c in circles if c[1] is not None and c[2] is not None]
        fit = doc.get(env) if isinstance(doc.get(env), dict) else {}
        if num(fit.get("phi_deg")) is None:
            fit = {"refused": str(fit.get("refused", "not in mohr_coulomb.json"))}
        out[env] = {"circles": circles, "fit": fit,
                    "left_out": [r.name for r in runs if all(c[0] is not r for c in circles)]}
    return out


def sigma3_label(run, runs):
    """Legend label: sigma_3 in kPa, with the run's name when another run has the same sigma_3 and its grain
    class when the runs' classes differ."""
    s3 = triaxial_sigma3(run)
    text = f"σ$_3$ = {fmt(None if s3 is None else 1e-3 * s3, '.4g', 'kPa')}".replace("&mdash;", "?")
    same = [r for r in runs if triaxial_sigma3(r) == s3]
    extra = []
    if len({r.preset for r in runs}) > 1:
        extra.append(run.preset)
    if len(same) > 1:
        extra.append(run.name)
    return text + (f" ({', '.join(extra)})" if extra else "")


def fig_triaxial_overlay(runs, out_dir):
    f = Figure("Stress ratio and volumetric strain of all runs", "ASTM D7181",
               "Top: q/p' against axial strain, the dot at each run's peak (run.json); bottom: volumetric strain, "
               "compression positive (dilation falls); one colour per run, labelled by its cell pressure "
               "&sigma;<sub>3</sub>.")
    col = run_colors(runs)
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 7.4), sharex=True)
    for r in runs:
        ea, eta, ev = r.col("axial_strain"), r.col("stress_ratio"), r.col("volumetric_strain")
        if ea is None or eta is None:
            f.missing(f"{r.name}/series.csv columns axial_strain and stress_ratio")
            continue
        a1.plot(100 * ea, eta, color=col[id(r)], lw=1.4, label=sigma3_label(r, runs))
        ep, etap = num(get(r.info, "triaxial", "axial_strain_at_peak")), num(get(r.info, "triaxial", "peak_stress_ratio"))
        if ep is not None and etap is not None:
            a1.plot([100 * ep], [etap], "o", color=col[id(r)], ms=5)
        if ev is not None:
            a2.plot(100 * ea, 100 * ev, color=col[id(r)], lw=1.4)
        else:
            f.missing(f"{r.name}/series.csv column volumetric_strain")
    a1.set_ylabel("stress ratio q/p' (–)")
    a1.set_ylim(bottom=0)
    a1.set_title("(a) stress ratio")
    a1.legend(loc="lower right")
    a2.axhline(0, color="0.3", lw=0.8)
    a2.set_ylabel("volumetric strain $\\varepsilon_v$ (%, compression +)")
    a2.set_xlabel("axial strain $\\varepsilon_a$ (%)")
    a2.set_xlim(left=0)
    a2.set_title("(b) volumetric strain")
    fig.tight_layout()
    return f.save(fig, out_dir, "triaxial_overlay.png")


def fig_stress_paths(runs, out_dir):
    f = Figure("Stress paths in p'-q", "ASTM D7181",
               "Deviator stress q against mean effective stress p' during shear, one colour per run: each starts "
               "at p' = &sigma;<sub>3</sub> and rises along a slope of 3 (constant &sigma;<sub>3</sub>); dots: the "
               "peak of q/p' (run.json's strain), squares: the last sample; dotted: each run's critical-state line "
               "q = &eta;<sub>cs</sub> p' (run.json's critical_stress_ratio).")
    col = run_colors(runs)
    fig, ax = plt.subplots(figsize=(7.0, 4.8))
    pmax = 0.0
    for r in runs:
        p, q, ea = r.col("mean_stress_Pa"), r.col("deviator_stress_Pa"), r.col("axial_strain")
        if p is None or q is None:
            f.missing(f"{r.name}/series.csv columns mean_stress_Pa and deviator_stress_Pa")
            continue
        ax.plot(1e-3 * p, 1e-3 * q, color=col[id(r)], lw=1.2, label=sigma3_label(r, runs))
        ep = num(get(r.info, "triaxial", "axial_strain_at_peak"))
        if ep is not None and ea is not None:
            k = int(np.nanargmin(np.abs(ea - ep)))
            ax.plot([1e-3 * p[k]], [1e-3 * q[k]], "o", color=col[id(r)], ms=5)
        ax.plot([1e-3 * p[-1]], [1e-3 * q[-1]], "s", color=col[id(r)], ms=5)
        pmax = max(pmax, float(np.nanmax(p)))
    for r in runs:
        eta = num(get(r.info, "triaxial", "critical_stress_ratio"))
        if eta is not None and pmax > 0:
            ax.plot([0, 1.05e-3 * pmax], [0, 1.05e-3 * pmax * eta], ":", color=col[id(r)], lw=1.0)
    ax.plot([], [], ":", color="0.4", lw=1.0, label="q = $\\eta_{cs}$ p' of each run (run.json)")
    ax.set_xlim(0, 1.05e-3 * pmax if pmax > 0 else None)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("mean effective stress p' (kPa)")
    ax.set_ylabel("deviator stress q (kPa)")
    ax.legend(loc="upper left")
    ax.set_title("Stress paths")
    return f.save(fig, out_dir, "stress_paths.png")


def fig_mohr_circles(runs, mohr, out_dir):
    f = Figure("Mohr circles and the Mohr-Coulomb envelopes", "Mohr-Coulomb",
               "Shear stress &tau; against normal effective stress &sigma;' (equal scales, so circles are round). "
               "For each run the circle at the peak (solid) and at the critical state (dashed), from "
               "&sigma;<sub>3</sub> = the run's consolidation normal stress (config.consolidation.normal_stress, "
               "the cell pressure the sides hold) and &sigma;<sub>1</sub> = &sigma;<sub>3</sub> (3 + 2&eta;)/(3 &minus; "
               "&eta;) with &eta; = run.json's triaxial.peak_stress_ratio or critical_stress_ratio (q/p' averaged "
               "over 1 % of axial strain at the peak, over the last fifth at the critical state). Black: the "
               "envelopes &tau; = c' + &sigma;' tan &phi;' fitted over the runs (least squares of t = "
               "(&sigma;<sub>1</sub> &minus; &sigma;<sub>3</sub>)/2 on s' = (&sigma;<sub>1</sub> + "
               "&sigma;<sub>3</sub>)/2, t = c' cos &phi;' + s' sin &phi;'); small dots: where each circle touches "
               "its fitted envelope; all from mohr_coulomb.json, which grainlab report writes.")
    if mohr is None:
        return f.missing(*MOHR_MISSING)
    if not mohr["peak"]["circles"] and not mohr["critical_state"]["circles"]:
        return f.missing("run.json triaxial.peak_stress_ratio, critical_stress_ratio or "
                         "config.consolidation.normal_stress", "in every run")
    for env, _, _, what in ENVELOPES:
        if mohr[env]["left_out"]:
            f.missing(f"the {what} stresses of " + ", ".join(mohr[env]["left_out"]), "no circle drawn")
    col = run_colors(runs)
    fig, ax = plt.subplots(figsize=(8.0, 5.6))
    th = np.linspace(0, math.pi, 181)
    smax = rmax = 0.0
    for env, ls in (("peak", "-"), ("critical_state", "--")):
        for r, s1, s3 in mohr[env]["circles"]:
            c, rad = 0.5e-3 * (s1 + s3), 0.5e-3 * (s1 - s3)
            ax.plot(c + rad * np.cos(th), rad * np.sin(th), ls, color=col[id(r)], lw=1.3,
                    label=sigma3_label(r, runs) if env == "peak" else None)
            smax, rmax = max(smax, 1e-3 * s1), max(rmax, rad)
    xs = np.array([0.0, 1.08 * smax])
    for env, ls, color, what in (("peak", "-", "black", "peak"), ("critical_state", "--", "0.4", "critical state")):
        fit = mohr[env]["fit"]
        if "refused" in fit:
            continue
        tan_phi = math.tan(math.radians(fit["phi_deg"]))
        c = tidy(1e-3 * fit["c_Pa"])
        ax.plot(xs, c + tan_phi * xs, ls, color=color, lw=1.1,
                label=f"{what}: $\\phi'$ = {fit['phi_deg']:.2f}°, $c'$ = {c:.2f} kPa")
        sphi, cphi = fit["sin_phi"], math.cos(math.radians(fit["phi_deg"]))
        for r, s1, s3 in mohr[env]["circles"]:
            cc, rad = 0.5e-3 * (s1 + s3), 0.5e-3 * (s1 - s3)
            ax.plot([cc - rad * sphi], [rad * cphi], ".", color=color, ms=5)
    for env, _, _, what in ENVELOPES:
        if "refused" in mohr[env]["fit"]:
            f.notes.append(f"no {what} envelope: {mohr[env]['fit']['refused']}")
    # A proxy so the legend says which line style is which state.
    ax.plot([], [], "-", color="0.5", lw=1.3, label="circle at the peak")
    ax.plot([], [], "--", color="0.5", lw=1.3, label="circle at the critical state")
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlim(0, 1.08 * smax)
    ax.set_ylim(0, 1.25 * rmax)
    ax.set_xlabel("normal effective stress $\\sigma'$ (kPa)")
    ax.set_ylabel("shear stress $\\tau$ (kPa)")
    # Below the axes: inside, it would cover the envelopes, which cross the whole plot.
    # Its top 44 points under the axes whatever their height (equal scales): clear of the tick labels and x label.
    below = matplotlib.transforms.offset_copy(ax.transAxes, fig=fig, y=-44, units="points")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, 0.0), bbox_transform=below, fontsize=8, ncol=2)
    ax.set_title("Mohr circles at the peak and at the critical state")
    return f.save(fig, out_dir, "mohr_circles.png")


def mohr_fit_table(runs, mohr):
    head = ["envelope", "&phi;' fitted (deg)", "c' fitted (kPa)", "R<sup>2</sup>", "rms residual of t (kPa)",
            "runs", "&phi;' of each run alone, c' = 0 (deg, run.json)"]
    if mohr is None:
        return f'<div class="note">not available: {html.escape(" missing (".join(MOHR_MISSING))})</div>'
    rows = []
    for env, _, angle, what in ENVELOPES:
        fit = mohr[env]["fit"]
        alone = ", ".join(fmt(get(r.info, "triaxial", angle), ".2f") for r, _, _ in mohr[env]["circles"])
        if "refused" in fit:
            rows.append([what, "&mdash;", "&mdash;", "&mdash;", "&mdash;", str(len(mohr[env]["circles"])),
                         alone or "&mdash;"])
            continue
        exact = " (two runs: the exact line)" if fit["runs"] == 2 else ""
        rows.append([what, fmt(fit["phi_deg"], ".2f"), fmt(tidy(1e-3 * fit["c_Pa"]), ".2f"), fmt(fit["r_squared"], ".5f"),
                     fmt(1e-3 * fit["rms_residual_Pa"], ".3g"), f"{fit['runs']}{exact}", alone])
    notes = "".join(f'<div class="note">no {what} envelope: {html.escape(mohr[env]["fit"]["refused"])}</div>'
                    for env, _, _, what in ENVELOPES if "refused" in mohr[env]["fit"])
    return grid_html(head, rows, "Mohr-Coulomb envelopes &tau; = c' + &sigma;' tan &phi;' fitted over the runs "
                                 "(least squares of t on s', from mohr_coulomb.json), beside each run's own angle "
                                 "(in the order of the table below)") + notes


def triaxial_comparison_table(runs, out_dir):
    head = ["run", "grain class", "&sigma;<sub>3</sub> (kPa)", "peak q/p'", "&epsilon;<sub>a</sub> at peak (%)",
            "&phi;'<sub>p</sub> (deg)", "critical q/p'", "&phi;'<sub>cs</sub> (deg)", "&psi;<sub>p</sub> (deg)",
            "E<sub>50</sub> (MPa)", "e at shear", "final e", "wall time (h)"]
    rows = []
    for r in runs:
        t = lambda k: get(r.info, "triaxial", k)
        s3, e50, ep = triaxial_sigma3(r), num(t("e50_Pa")), num(t("axial_strain_at_peak"))
        wall = num(get(r.info, "timings", "wall_s"))
        rows.append([run_link(r, out_dir), esc(r.preset), fmt(None if s3 is None else 1e-3 * s3, ".4g"),
                     fmt(t("peak_stress_ratio"), ".4f"), fmt(None if ep is None else 100 * ep, ".2f"),
                     fmt(t("peak_friction_angle_deg"), ".2f"), fmt(t("critical_stress_ratio"), ".4f"),
                     fmt(t("critical_friction_angle_deg"), ".2f"), fmt(t("peak_dilatancy_angle_deg"), ".2f"),
                     fmt(None if e50 is None else 1e-6 * e50, ".4g"), fmt(t("void_ratio_at_shear"), ".4f"),
                     fmt(t("final_void_ratio"), ".4f"), fmt(None if wall is None else wall / 3600, ".2f")])
    return grid_html(head, rows, "Each run (run.json's triaxial group; &phi;' from sin &phi;' = 3&eta;/(6 + &eta;), "
                                 "c' = 0; a run's name links to its own report when it has one)")


def triaxial_comparison_report(runs, out_dir):
    runs = sorted(runs, key=lambda r: (triaxial_sigma3(r) is None, triaxial_sigma3(r) or 0.0))
    prepare_out(out_dir, COMPARISON_PNGS + TRIAXIAL_COMPARISON_PNGS)  # mohr_coulomb.json is grainlab report's
    mohr = read_mohr(runs, out_dir)
    figs = [fig_triaxial_overlay(runs, out_dir), fig_stress_paths(runs, out_dir), fig_mohr_circles(runs, mohr, out_dir)]
    subtitle = (f"{len(runs)} drained triaxial runs, by cell pressure: " + ", ".join(
        f"<code>{html.escape(r.name)}</code> ({esc(r.preset)}, &sigma;<sub>3</sub> = "
        f"{fmt(1e-3 * (triaxial_sigma3(r) or float('nan')), '.4g', 'kPa')})" for r in runs) +
        ('. The fitted envelopes are in <a href="mohr_coulomb.json">mohr_coulomb.json</a>.' if mohr is not None
         else "."))
    blocks = ["<h2>Mohr-Coulomb strength parameters</h2>", mohr_fit_table(runs, mohr),
              "<h2>Runs</h2>", triaxial_comparison_table(runs, out_dir), "<h2>Figures</h2>"]
    blocks += [figure_html(f) for f in figs]
    return write_page(out_dir, "grainlab triaxial comparison report", subtitle, blocks), figs
