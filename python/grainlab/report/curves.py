"""Curves of one direct shear run against shear strain: stress ratio F/N (paper Fig. 10a),
mean grain rotation (Fig. 13) and coordination number (Fig. 14)."""

import numpy as np

from .plotting import ALL_COLOR, BAND_COLOR, Figure, all_band_figure, pct_axis, plt
from .reading import NO_PEAK, get, num


def fig_stress_ratio(run, out_dir):
    """Fig. 10a: F/N against shear strain, with the peak marked and phi = atan(F/N) on the right."""
    f = Figure("Stress ratio against shear strain", "Fig. 10a",
               "Shear force on the upper half over the normal force on the cap, F/N, against shear strain "
               "d<sub>h</sub>/L. The right axis reads the mobilised friction angle &phi; = atan(F/N) (Eq. 18); "
               "the dot marks the peak, or the largest F/N where that lies in the last 5 % of the test's strain "
               "(no peak reached: the curve may still be rising).")
    r = run.col("stress_ratio")
    if r is None:
        return f.missing("series.csv column stress_ratio")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.plot(run.strain_pct, r, color=ALL_COLOR, lw=1.6, label="F/N")
    phi_p, e_p, is_peak = run.peak_friction()
    rp = num(get(run.info, "peaks", "stress_ratio"))
    if phi_p is not None and e_p is not None and rp is not None:
        what, phi = ("peak", "$\\phi_p$") if is_peak else ("largest (at the end, no peak)", "$\\phi$")
        if not is_peak:
            f.notes.append(NO_PEAK.format(what="F/N"))
        ax.plot([100 * e_p], [rp], "o", color=BAND_COLOR, zorder=5,
                label=f"{what}: F/N = {rp:.3f}, {phi} = {phi_p:.1f}° at $\\varepsilon_s$ = {100 * e_p:.1f} %")
        ax.legend(loc="lower right")
    pct_axis(ax)
    ax.set_ylim(bottom=min(0.0, float(np.nanmin(r))))
    ax.set_ylabel("stress ratio F/N (–)")
    sec = ax.secondary_yaxis("right", functions=(lambda t: np.degrees(np.arctan(t)),
                                                 lambda p: np.tan(np.radians(np.clip(p, -89.9, 89.9)))))
    sec.set_ylabel("friction angle $\\phi$ = atan(F/N) (deg)")
    ax.set_title("Stress ratio F/N")
    return f.save(fig, out_dir, "stress_ratio.png")


def fig_rotation(run, out_dir):
    """Fig. 13: mean grain rotation angle, all grains and band, against strain."""
    return all_band_figure(
        run, out_dir, "rotation.png", ("rotation_mean_deg", "rotation_band_deg"),
        "mean rotation angle $\\theta_\\mathrm{mean}$ (deg)", "Mean grain rotation", "Fig. 13",
        "Mean rotation angle &theta; = 2 acos(q<sub>0</sub>) (Eq. 21) of the grains since the start of shear, "
        "over all grains and over the grains in the shear band, against shear strain.")


def fig_coordination(run, out_dir):
    """Fig. 14: coordination number, all grains and band, against strain."""
    return all_band_figure(
        run, out_dir, "coordination_number.png", ("coordination_number", "coordination_number_band"),
        "coordination number CN = 2 $N_c$ / $N_p$ (–)", "Coordination number", "Fig. 14",
        "Coordination number CN = 2 N<sub>c</sub>/N<sub>p</sub> (Eq. 22), grain-grain contacts per grain, "
        "over all grains and over the grains in the shear band, against shear strain.")
