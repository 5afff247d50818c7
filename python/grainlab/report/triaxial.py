"""The triaxial report of one run (config.test = "triaxial"): q/p' and volumetric strain
against axial strain, the stress path, and run.json's triaxial results."""

import html

import numpy as np

from .html_page import SINGLE_PNGS, esc, figure_html, fmt, fmt_duration, prepare_out, table_html, write_page
from .plotting import ALL_COLOR, BAND_COLOR, Figure, plt
from .reading import get, num
from .tables import inputs_rows, preparation_rows


# ---------------------------------------------------------------------------
# The drained triaxial test (config.test = "triaxial"): series rows every
# output.strain_interval of axial strain (axial_strain, volumetric_strain
# (compression positive), axial_stress_Pa, cell_pressure_Pa,
# deviator_stress_Pa, mean_stress_Pa, stress_ratio q/p', side_stress_error,
# void_ratio, ...) and run.json's "triaxial" group (peak_stress_ratio,
# axial_strain_at_peak, peak_friction_angle_deg, critical_stress_ratio,
# critical_friction_angle_deg, critical_dilatancy_angle_deg (over the same
# last fifth; absent in runs before 2026-12-05), peak_dilatancy_angle_deg, e50_Pa,
# void_ratio_at_shear, final_void_ratio).

def critical_state_label(run):
    """Legend of the last fifth's q/p' in a triaxial: a critical state only
    where the specimen no longer changes volume there, so its dilatancy angle
    is shown beside it (runs before 2026-12-05 lack it)."""
    t = lambda k: num(get(run.info, "triaxial", k))
    eta, phi, psi = t("critical_stress_ratio"), fmt(t("critical_friction_angle_deg"), ".1f"), \
        t("critical_dilatancy_angle_deg")
    if psi is None:
        return f"critical state (last fifth) {eta:.3f} ($\\phi$ = {phi}°)"
    return f"last fifth {eta:.3f} ($\\phi$ = {phi}°, $\\psi$ = {psi:.1f}°; critical state: $\\psi$ = 0)"


def fig_triaxial_curves(run, out_dir):
    f = Figure("Stress ratio and volumetric strain against axial strain", "ASTM D7181",
               "Top: q/p' against axial strain, with the peak (averaged over 1 % of strain) and the mean over "
               "the last fifth of the strain from run.json, with the dilatancy angle there: that mean is the "
               "critical state only if the angle is about 0 (a specimen still dilating gives an upper bound); "
               "bottom: volumetric strain, compression positive, so dilation falls.")
    ea, eta, ev = run.col("axial_strain"), run.col("stress_ratio"), run.col("volumetric_strain")
    if ea is None or eta is None or ev is None:
        return f.missing("series.csv columns axial_strain, stress_ratio and volumetric_strain")
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(6.4, 6.0), sharex=True)
    a1.plot(100 * ea, eta, color=ALL_COLOR, lw=1.4, label="q/p'")
    t = lambda k: num(get(run.info, "triaxial", k))
    if t("peak_stress_ratio") is not None and t("axial_strain_at_peak") is not None:
        a1.plot([100 * t("axial_strain_at_peak")], [t("peak_stress_ratio")], "o", color=BAND_COLOR,
                label=f"peak {t('peak_stress_ratio'):.3f} ($\\phi_p$ = {fmt(t('peak_friction_angle_deg'), '.1f')}°)")
    if t("critical_stress_ratio") is not None:
        a1.axhline(t("critical_stress_ratio"), color="#555555", ls="--", lw=1.0,
                   label=critical_state_label(run))
    a1.set_ylabel("stress ratio q/p' (–)")
    a1.legend(loc="lower right")
    a1.set_title("Drained triaxial compression")
    a2.plot(100 * ea, 100 * ev, color=ALL_COLOR, lw=1.4)
    a2.set_xlabel("axial strain $\\varepsilon_a$ (%)")
    a2.set_ylabel("volumetric strain $\\varepsilon_v$ (%, compression +)")
    a2.set_xlim(left=0)
    return f.save(fig, out_dir, "triaxial_curves.png")


def fig_stress_path(run, out_dir):
    f = Figure("Stress path in p'-q", "ASTM D7181",
               "The deviator stress q against the mean effective stress p' during shear (a drained test at "
               "constant &sigma;<sub>3</sub> follows a line of slope 3 from the isotropic state); the dashed line "
               "is q = &eta; p' with &eta; the q/p' of the last fifth of the strain: the critical-state line where "
               "the specimen no longer changes volume there (see the dilatancy angle in the table).")
    p, q = run.col("mean_stress_Pa"), run.col("deviator_stress_Pa")
    if p is None or q is None:
        return f.missing("series.csv columns mean_stress_Pa and deviator_stress_Pa")
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(1e-3 * p, 1e-3 * q, color=ALL_COLOR, lw=1.2, label="stress path")
    eta = num(get(run.info, "triaxial", "critical_stress_ratio"))
    if eta is not None:
        xs = np.array([0, 1e-3 * float(np.nanmax(p)) * 1.1])
        ax.plot(xs, eta * xs, "--", color="#555555", lw=1.0, label=f"q = {eta:.3f} p'")
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=min(0.0, 1e-3 * float(np.nanmin(q))))
    ax.set_xlabel("mean effective stress p' (kPa)")
    ax.set_ylabel("deviator stress q (kPa)")
    ax.legend(loc="upper left")
    ax.set_title("Stress path")
    return f.save(fig, out_dir, "stress_path.png")


def triaxial_results_rows(run):
    t = lambda k: get(run.info, "triaxial", k)
    inertial, err = run.col("inertial_number"), run.col("side_stress_error")
    return [
        ("peak friction angle &phi;'<sub>p</sub> (q/p')", fmt(t("peak_friction_angle_deg"), ".2f", "deg") +
         f" at &epsilon;<sub>a</sub> = {fmt(100 * (num(t('axial_strain_at_peak')) or float('nan')), '.2f', '%')}"),
        ("friction angle over the last fifth (&phi;'<sub>cs</sub> if at constant volume)",
         fmt(t("critical_friction_angle_deg"), ".2f", "deg")),
        ("dilatancy angle over the last fifth (0 at a critical state)",
         fmt(t("critical_dilatancy_angle_deg"), ".2f", "deg")),
        ("peak dilatancy angle &psi;<sub>p</sub>", fmt(t("peak_dilatancy_angle_deg"), ".2f", "deg")),
        ("secant modulus E<sub>50</sub>", fmt(1e-6 * (num(t("e50_Pa")) or float("nan")), ".4g", "MPa")),
        ("void ratio at the start of shear / at the end", f"{fmt(t('void_ratio_at_shear'), '.4f')} / "
                                                          f"{fmt(t('final_void_ratio'), '.4f')}"),
        *preparation_rows(run),
        ("&sigma;<sub>3</sub> held: side stress error, mean / worst",
         "&mdash;" if err is None else f"{100 * np.nanmean(err[1:]):.2f} % / {100 * np.nanmax(err[1:]):.2f} %"),
        ("inertial number I, max during shear", fmt(None if inertial is None else np.nanmax(inertial), ".2e")),
        ("wall time", fmt_duration(get(run.info, "timings", "wall_s"))),
        ("steps / simulated time", f"{esc(get(run.info, 'timings', 'steps'))} / "
                                   f"{fmt(get(run.info, 'timings', 'simulated_s'), '.4g', 's')}"),
    ]


def triaxial_report(run, out_dir):
    prepare_out(out_dir, SINGLE_PNGS)
    figs = [fn(run, out_dir) for fn in (fig_triaxial_curves, fig_stress_path)]
    inputs = [r for r in inputs_rows(run) if not r[0].startswith(("gap between", "shear speed", "final strain"))]
    inputs.insert(8, ("final axial strain", fmt(100 * (num(get(run.info, "config", "triaxial", "final_strain"))
                                                      or float("nan")), ".3g", "%")))
    subtitle = (f"Drained triaxial run <code>{html.escape(run.name)}</code> (folder <code>"
                f"{html.escape(str(run.dir.resolve()))}</code>): grain class {esc(run.preset)}, sand preset "
                f"{esc(run.sand)}, {esc(get(run.info, 'grains'))} grains between rigid servo-held walls "
                f"(&sigma;<sub>3</sub> = consolidation normal stress).")
    blocks = ['<h2>Inputs and results</h2>\n<div class="tables">',
              table_html(inputs, "Inputs (run.json)"),
              table_html(triaxial_results_rows(run), "Results"), "</div>", "<h2>Figures</h2>"]
    blocks += [figure_html(f) for f in figs]
    return write_page(out_dir, f"grainlab triaxial report: {run.name}", subtitle, blocks), figs
