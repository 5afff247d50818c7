"""The tables of one run: its inputs, its preparation and the direct shear peaks and results
(run.json's numbers, formatted)."""

import numpy as np

from .html_page import esc, fmt, fmt_duration
from .reading import get, num


def inputs_rows(run):
    """(label, value HTML) rows of the run's inputs, from run.json."""
    i, c = run.info, lambda *k: get(run.info, "config", *k)
    box = [num(c("box", k)) for k in ("length", "width", "height")]
    box_s = (" &times; ".join(f"{1e3 * b:.2f}" for b in box) + " mm") if all(b is not None for b in box) else "&mdash;"
    folder = c("grains", "folder")
    rows = [
        ("grain class (config.grains.preset)", esc(run.preset) + (f" (meshes from {esc(folder)})" if folder else "")),
        ("sand preset (config.material.preset)", esc(run.sand)),
        ("grains", esc(get(i, "grains"))),
        ("mean equivalent diameter", fmt(1e3 * (num(get(i, "mean_equivalent_diameter_m")) or float("nan")), ".3f", "mm")),
        ("sieve range d<sub>min</sub>&ndash;d<sub>max</sub>",
         f"{fmt(1e3 * (num(c('grains', 'd_min')) or float('nan')), '.3f')} &ndash; "
         f"{fmt(1e3 * (num(c('grains', 'd_max')) or float('nan')), '.3f', 'mm')}"),
        ("box L &times; W &times; H", box_s),
        ("gap between the halves", fmt(1e3 * (num(c("box", "gap")) or float("nan")), ".2f", "mm")),
        ("normal stress &sigma;<sub>n</sub>", fmt(1e-3 * (num(c("consolidation", "normal_stress")) or float("nan")), ".4g", "kPa")),
        ("inter-grain friction &mu;", fmt(c("material", "friction"))),
        ("wall friction", fmt(c("material", "wall_friction"))),
        ("contact law", esc(c("material", "contact_law"))),
        ("grain density", fmt(c("material", "density"), ".4g", "kg/m<sup>3</sup>")),
        ("density scaling (used)", fmt(get(i, "density_scaling"))),
        ("time step", fmt(get(i, "time_step_s"), ".3g", "s")),
        ("shear speed", fmt(get(i, "shear_speed_m_per_s"), ".3g", "m/s")),
        ("final strain (target)", fmt(100 * (num(c("shear", "final_strain")) or float("nan")), ".3g", "%")),
        ("target Dr / target e", f"{fmt(100 * (num(c('specimen', 'relative_density')) or float('nan')), '.1f', '%')} / "
                                 f"{fmt(get(i, 'preparation', 'target_void_ratio'), '.4f')}"),
        ("seed", esc(get(i, "seed"))),
        ("grainlab version", esc(get(i, "grainlab_version"))),
    ]
    return rows


def preparation_rows(run):
    """(label, value HTML) rows of the prepared specimen's two void ratios and its relative density, named by
    the void ratio and the index void ratios the engine computed D_r on: the grains' own e_min/e_max go with
    the bulk void ratio (away from the walls), the lab's (config.specimen) with the whole specimen's."""
    prep = lambda k: num(get(run.info, "preparation", k))
    dr, own = prep("relative_density"), prep("relative_density_own")
    if dr is not None and own is not None and dr == own:
        on, indices = "bulk e", (f"the grains' own e<sub>min</sub> / e<sub>max</sub> {fmt(prep('own_e_min'), '.3f')}"
                                 f" / {fmt(prep('own_e_max'), '.3f')}")
    else:
        c = lambda k: get(run.info, "config", "specimen", k)
        on, indices = "whole specimen e", (f"the lab's e<sub>min</sub> / e<sub>max</sub> {fmt(c('e_min'), '.3f')}"
                                           f" / {fmt(c('e_max'), '.3f')}")
    return [
        ("void ratio after preparation, whole specimen e", fmt(prep("void_ratio"), ".4f")),
        ("void ratio after preparation, bulk e (away from the walls)", fmt(prep("bulk_void_ratio"), ".4f")),
        (f"achieved relative density D<sub>r</sub>, on the {on}",
         fmt(None if dr is None else 100 * dr, ".1f", "%") + ("" if dr is None else f" ({indices})")),
    ]


def results_rows(run):
    """(label, value HTML) rows of the run's peak and final values."""
    i = run.info
    phi_p, e_phi, phi_is_peak = run.peak_friction()
    psi_p, e_psi, psi_is_peak = run.peak_dilation()
    def at(e, is_peak):
        if e is None:
            return ""
        end = "" if is_peak else " (the end of the test: no peak reached)"
        return f" at &epsilon;<sub>s</sub> = {fmt(100 * e, '.2f', '%')}{end}"
    inertial = run.col("inertial_number")
    unb = run.col("unbalanced_force_ratio")
    rows = [
        ("peak friction angle &phi;<sub>p</sub>", fmt(phi_p, ".2f", "deg") + at(e_phi, phi_is_peak)),
        ("peak stress ratio F/N", fmt(get(i, "peaks", "stress_ratio"), ".4f")),
        ("peak dilation angle &psi;<sub>p</sub>", fmt(psi_p, ".2f", "deg") + at(e_psi, psi_is_peak)),
        ("peak fabric factor &Psi;<sub>p</sub>, all / band",
         f"{fmt(run.peak_psi(), '.4f')} / {fmt(run.peak_psi(band=True), '.4f')}"),
        ("final friction angle (last 10 % of the test)", fmt(get(i, "final", "friction_angle_deg"), ".2f", "deg")),
        ("final dilation angle (last 10 % of the test)", fmt(get(i, "final", "dilation_angle_deg"), ".2f", "deg")),
        *preparation_rows(run),
        ("final void ratio (whole specimen)", fmt(get(i, "final", "void_ratio"), ".4f")),
        ("mean grain roundness R", fmt(get(i, "mean_roundness"), ".3f")),
        ("inertial number I, max during shear",
         fmt(None if inertial is None else np.nanmax(inertial), ".2e") +
         ("" if inertial is None else (" (quasi-static: I &lt; 10<sup>&minus;3</sup>)" if np.nanmax(inertial) < 1e-3
                                       else " (<b>above 10<sup>&minus;3</sup>: not quasi-static</b>)"))),
        ("unbalanced force ratio, median during shear", fmt(None if unb is None else np.nanmedian(unb), ".3g")),
        ("wall time", fmt_duration(get(i, "timings", "wall_s"))),
        ("steps / simulated time", f"{esc(get(i, 'timings', 'steps'))} / {fmt(get(i, 'timings', 'simulated_s'), '.4g', 's')}"),
        ("samples in series.csv", str(len(run.series["shear_strain"]))),
    ]
    return rows
