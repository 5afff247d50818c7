"""The oedometer report (config.test = "oedometer"): e against log sigma', K0 and the
constrained modulus, with run.json's oedometer results."""

import html

import numpy as np
import matplotlib.ticker

from .html_page import SINGLE_PNGS, esc, figure_html, fmt, fmt_duration, prepare_out, table_html, write_page
from .plotting import ALL_COLOR, BAND_COLOR, Figure, plt
from .reading import get, num
from .tables import inputs_rows, preparation_rows


# ---------------------------------------------------------------------------
# The oedometer (config.test = "oedometer"): one series row per load stage at
# rest (stage, target_stress_Pa, vertical_stress_Pa, floor_stress_Pa,
# lateral_stress_Pa, K0, vertical_strain, cap_height_m, void_ratio,
# constrained_modulus_Pa, ...) and run.json's "oedometer" group
# (compression_index, swelling_index, max_stress_Pa, K0_at_max_stress,
# constrained_modulus_at_max_stress_Pa, modulus_stress_exponent,
# final_void_ratio). Stage 0 is the consolidated specimen.

def oedometer_constant_rate(run):
    return get(run.info, "config", "oedometer", "loading", default="stages") == "constant-rate"


def oedometer_stage_ends(run):
    """Indices of each stage's last row: with stages, every row; at a constant rate, where each stage's stress
    was reached (the summary's rows, lab/oedometer.h)."""
    stage = run.series["stage"]
    return np.array([i for i in range(len(stage)) if i + 1 == len(stage) or stage[i + 1] != stage[i]], dtype=int)


def oedometer_branches(run):
    """Boolean masks of the loading rows (stage 0 and the rows of each stage whose stress is above the stage
    before's) and the unloading rows."""
    stage, t = run.series["stage"], run.series["target_stress_Pa"]
    target = {}
    for s_, t_ in zip(stage, t):
        target[int(s_)] = t_
    load = np.array([s_ == 0 or target[int(s_)] > target.get(int(s_) - 1, -np.inf) for s_ in stage], dtype=bool)
    return load, ~load


def oedometer_markers(run, values, load, unload, ax, label_load, label_unload):
    """The whole curve as a line, and dots at the stages' ends (filled: loading, open: unloading)."""
    ends = np.zeros(len(load), dtype=bool)
    ends[oedometer_stage_ends(run)] = True
    sv = run.col("vertical_stress_Pa")
    ax.plot(1e-3 * sv, values, color="#999999", lw=1.0, zorder=1)
    ax.plot(1e-3 * sv[load & ends], values[load & ends], "o", color=ALL_COLOR, label=label_load)
    if np.any(unload & ends):
        ax.plot(1e-3 * sv[unload & ends], values[unload & ends], "o", mfc="white", color=BAND_COLOR,
                label=label_unload)


def oedometer_how(run):
    return ("at a constant rate of strain: the line is every row, the dots where each stage's stress was reached"
            if oedometer_constant_rate(run) else "at rest at the end of every load stage")


def stress_ticks(ax, kpa, axis="x"):
    """Plain tick labels at the given stresses (kPa) on a log axis."""
    ticks = sorted(set(float(f"{v:.3g}") for v in kpa if np.isfinite(v) and v > 0))
    (ax.set_xticks if axis == "x" else ax.set_yticks)(ticks, [f"{v:g}" for v in ticks])
    (ax.xaxis if axis == "x" else ax.yaxis).set_minor_formatter(matplotlib.ticker.NullFormatter())


def fig_e_log_sigma(run, out_dir):
    constant_rate = run.col("stage") is not None and oedometer_constant_rate(run)
    f = Figure("Void ratio against vertical stress (e-log sigma)", "ASTM D4186" if constant_rate else "ASTM D2435",
               f"Void ratio {oedometer_how(run)}, against the cap's vertical stress on a "
               "log scale; filled: loading, open: unloading. C<sub>c</sub> and C<sub>s</sub> are run.json's "
               "(oedometer group): the last loading increment before the first unloading, and the whole "
               "unloading branch after the largest stress.")
    e, sv = run.col("void_ratio"), run.col("vertical_stress_Pa")
    if e is None or sv is None or run.col("stage") is None:
        return f.missing("series.csv columns void_ratio, vertical_stress_Pa and stage")
    load, unload = oedometer_branches(run)
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    cc, cs = num(get(run.info, "oedometer", "compression_index")), num(get(run.info, "oedometer", "swelling_index"))
    oedometer_markers(run, e, load, unload, ax, f"loading (C$_c$ = {fmt(cc, '.4f')})",
                      f"unloading (C$_s$ = {fmt(cs, '.4f')})")
    ax.set_xscale("log")
    stress_ticks(ax, 1e-3 * sv[oedometer_stage_ends(run)])
    ax.set_xlabel("vertical stress $\\sigma_v$ (kPa, log scale)")
    ax.set_ylabel("void ratio e (–)")
    ax.legend(loc="best")
    ax.set_title("Compression curve")
    return f.save(fig, out_dir, "e_log_sigma.png")


def fig_k0(run, out_dir):
    f = Figure("Coefficient of lateral earth pressure at rest", "ASTM D2435",
               "K<sub>0</sub> = &sigma;<sub>h</sub>/&sigma;<sub>v</sub>: the mean normal stress on the four side "
               f"walls over the cap's stress, {oedometer_how(run)}; filled: loading, open: "
               "unloading (K<sub>0</sub> rises on unloading: the lateral stress is locked in). Jaky's "
               "1 &minus; sin &phi;' needs the test's friction angle, which the oedometer does not measure.")
    k0, sv = run.col("K0"), run.col("vertical_stress_Pa")
    if k0 is None or sv is None or run.col("stage") is None:
        return f.missing("series.csv columns K0, vertical_stress_Pa and stage")
    load, unload = oedometer_branches(run)
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    oedometer_markers(run, k0, load, unload, ax, "loading", "unloading")
    ax.set_xscale("log")
    stress_ticks(ax, 1e-3 * sv[oedometer_stage_ends(run)])
    ax.set_xlabel("vertical stress $\\sigma_v$ (kPa, log scale)")
    ax.set_ylabel("$K_0 = \\sigma_h / \\sigma_v$ (–)")
    ax.set_ylim(0, max(1.0, float(np.nanmax(k0)) * 1.1))
    ax.legend(loc="best")
    ax.set_title("K$_0$ against vertical stress")
    return f.save(fig, out_dir, "k0.png")


def fig_constrained_modulus(run, out_dir):
    f = Figure("Constrained modulus against stress", "Effective-medium theory",
               "M = &Delta;&sigma;<sub>v</sub>/&Delta;&epsilon;<sub>v</sub> of each loading increment (between "
               "the stages' ends) against its mean stress, log-log. The line is M ~ &sigma;<sup>n</sup> with "
               "run.json's n (least squares over the loading increments but the first); effective-medium theory "
               "of Hertz spheres with a fixed contact network gives n = 1/3, contacts forming under load raise it.")
    sv_all, eps_all = run.col("vertical_stress_Pa"), run.col("vertical_strain")
    if sv_all is None or eps_all is None or run.col("stage") is None:
        return f.missing("series.csv columns vertical_stress_Pa, vertical_strain and stage")
    ends = oedometer_stage_ends(run)
    sv, eps = sv_all[ends], eps_all[ends]
    load = oedometer_branches(run)[0][ends]
    m = np.full(len(sv), np.nan)
    mid = np.full(len(sv), np.nan)
    m[1:] = (sv[1:] - sv[:-1]) / (eps[1:] - eps[:-1])
    mid[1:] = 0.5 * (sv[1:] + sv[:-1])
    ok = load & np.isfinite(m) & (m > 0)
    if not np.any(ok):
        return f.missing("loading increments with a positive modulus")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    fitted = ok.copy()
    fitted[np.flatnonzero(ok)[0]] = False  # the first loading increment rearranges the preparation's stress: not fitted
    ax.plot(1e-3 * mid[fitted], 1e-6 * m[fitted], "o", color=ALL_COLOR, label="loading increments")
    first = ok & ~fitted
    ax.plot(1e-3 * mid[first], 1e-6 * m[first], "o", mfc="white", color=ALL_COLOR,
            label="first increment (not fitted)")
    n = num(get(run.info, "oedometer", "modulus_stress_exponent"))
    if n is not None and np.sum(fitted) >= 2:
        x = mid[fitted]
        c = np.exp(np.mean(np.log(m[fitted]) - n * np.log(x)))
        xs = np.geomspace(x.min(), x.max(), 50)
        ax.plot(1e-3 * xs, 1e-6 * c * xs ** n, "-", color=BAND_COLOR, label=f"M ~ σ$^{{{n:.2f}}}$")
    ax.set_xscale("log")
    ax.set_yscale("log")
    stress_ticks(ax, 1e-3 * mid[ok])
    stress_ticks(ax, 1e-6 * m[ok], axis="y")
    ax.set_xlabel("mean stress of the increment (kPa, log scale)")
    ax.set_ylabel("constrained modulus M (MPa, log scale)")
    ax.legend(loc="best")
    ax.set_title("Constrained modulus")
    return f.save(fig, out_dir, "constrained_modulus.png")


def oedometer_results_rows(run):
    i = run.info
    o = lambda k: get(i, "oedometer", k)
    unb = run.col("unbalanced_force_ratio")
    return [
        ("compression index C<sub>c</sub>", fmt(o("compression_index"), ".4f")),
        ("swelling index C<sub>s</sub>", fmt(o("swelling_index"), ".4f")),
        ("largest vertical stress", fmt(1e-3 * (num(o("max_stress_Pa")) or float("nan")), ".4g", "kPa")),
        ("K<sub>0</sub> at the largest stress", fmt(o("K0_at_max_stress"), ".3f")),
        ("constrained modulus at the largest stress",
         fmt(1e-6 * (num(o("constrained_modulus_at_max_stress_Pa")) or float("nan")), ".4g", "MPa")),
        ("power n of M ~ &sigma;<sup>n</sup> (loading)", fmt(o("modulus_stress_exponent"), ".3f")),
        *preparation_rows(run),
        ("final void ratio (whole specimen)", fmt(o("final_void_ratio"), ".4f")),
        ("unbalanced force ratio, largest at a stage's end", fmt(None if unb is None else np.nanmax(unb), ".3g")),
        ("wall time", fmt_duration(get(i, "timings", "wall_s"))),
        ("steps / simulated time", f"{esc(get(i, 'timings', 'steps'))} / {fmt(get(i, 'timings', 'simulated_s'), '.4g', 's')}"),
        ("loading", "constant rate of strain" if oedometer_constant_rate(run) else "stages held to rest"),
        ("stages / rows in series.csv", f"{len(oedometer_stage_ends(run))} / {len(run.series['stage'])}"),
    ]


def oedometer_report(run, out_dir):
    prepare_out(out_dir, SINGLE_PNGS)
    figs = [fn(run, out_dir) for fn in (fig_e_log_sigma, fig_k0, fig_constrained_modulus)]
    shear_only = ("gap between", "shear speed", "final strain")
    inputs = [r for r in inputs_rows(run) if not r[0].startswith(shear_only)]
    stresses = get(run.info, "config", "oedometer", "stresses", default=[])
    inputs.insert(8, ("load stages after consolidation",
                      ", ".join(fmt(1e-3 * x, ".4g") for x in stresses) + " kPa"))
    subtitle = (f"Oedometer run <code>{html.escape(run.name)}</code> (folder <code>{html.escape(str(run.dir.resolve()))}"
                f"</code>): grain class {esc(run.preset)}, sand preset {esc(run.sand)}, "
                f"{esc(get(run.info, 'grains'))} grains in a rigid square ring.")
    blocks = ['<h2>Inputs and results</h2>\n<div class="tables">',
              table_html(inputs, "Inputs (run.json)"),
              table_html(oedometer_results_rows(run), "Results"), "</div>", "<h2>Figures</h2>"]
    blocks += [figure_html(f) for f in figs]
    return write_page(out_dir, f"grainlab oedometer report: {run.name}", subtitle, blocks), figs
