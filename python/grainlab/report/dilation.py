"""Volume change of one direct shear run: the cap's vertical displacement against shear strain
with the engine's dilation angle (paper Fig. 10b)."""

import numpy as np

from .plotting import ALL_COLOR, BAND_COLOR, Figure, pct_axis, plt
from .reading import NO_PEAK


def fig_vertical_displacement(run, out_dir):
    """Fig. 10b: cap vertical displacement (mm, up = dilation) and the engine's dilation angle against strain."""
    f = Figure("Cap vertical displacement against shear strain", "Fig. 10b",
               "Vertical displacement of the top cap since the start of shear, d<sub>v</sub>, in mm; up "
               "(dilation) is positive, down (contraction) negative. Dashed, right axis: the dilation angle "
               "&psi; = atan(&Delta;d<sub>v</sub>/&Delta;d<sub>h</sub>) (Eq. 19) the engine computed "
               "(analysis/derived.csv); its peak &psi;<sub>p</sub> (run.json) is given in the legend.")
    dv = run.col("vertical_displacement_m")
    if dv is None:
        return f.missing("series.csv column vertical_displacement_m")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    psi_p, e_p, is_peak = run.peak_dilation()
    label = "cap displacement"
    if psi_p is not None and e_p is not None:
        if not is_peak:
            label += f" (largest $\\psi$ = {psi_p:.1f}° at the end, $\\varepsilon_s$ = {100 * e_p:.1f} %: no peak)"
            f.notes.append(NO_PEAK.format(what="the dilation angle"))
        else:
            label += f" ($\\psi_p$ = {psi_p:.1f}° at $\\varepsilon_s$ = {100 * e_p:.1f} %)"
    lines = ax.plot(run.strain_pct, 1e3 * dv, color=ALL_COLOR, lw=1.6, label=label)
    if psi_p is not None and e_p is not None:
        k = int(np.argmin(np.abs(run.series["shear_strain"] - e_p)))
        lines += ax.plot([run.strain_pct[k]], [1e3 * dv[k]], "o", color=BAND_COLOR, zorder=5,
                         label="steepest dilation")
    ax.axhline(0, color="0.3", lw=0.8)
    pct_axis(ax)
    ax.set_ylabel("cap vertical displacement $d_v$ (mm), up = dilation")
    d = run.derived()
    psi = None if d is None else d.get("dilation_angle_deg")
    if psi is None or "shear_strain" not in d or not np.any(np.isfinite(psi)):
        f.missing("analysis/derived.csv column dilation_angle_deg", "no dilation angle curve")
    else:
        ax2 = ax.twinx()
        lines += ax2.plot(100 * d["shear_strain"], psi, color=BAND_COLOR, lw=1.0, ls="--", alpha=0.8,
                          label="dilation angle $\\psi$ (right axis)")
        ax2.set_ylabel("dilation angle $\\psi$ (deg)")
        ax2.grid(False)
    ax.legend(lines, [ln.get_label() for ln in lines], loc="lower right")
    ax.set_title("Cap vertical displacement")
    return f.save(fig, out_dir, "vertical_displacement.png")
