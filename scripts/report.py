#!/usr/bin/python3
"""The grainlab run report: HTML and PNG figures for direct shear runs (paper Figs. 10-17), oedometer and
triaxial runs, any other lab test (every series column against its progress), and comparisons of direct
shear runs or of triaxial runs (Mohr circles, c' and phi').

Usage (Debian's Python, which has matplotlib and numpy):

    /usr/bin/python3 scripts/report.py RUN_DIR                 # -> RUN_DIR/report/index.html
    /usr/bin/python3 scripts/report.py RUN_A RUN_B [...]       # -> RUN_A/../comparison/report/index.html
    /usr/bin/python3 scripts/report.py RUN_DIR [...] --out DIR # -> DIR/index.html

One run folder gives a report of that run; several give a comparison report
that overlays their curves and tabulates their peaks against their mean grain
roundness (direct shear), or their curves, stress paths, Mohr circles and the
Mohr-Coulomb envelope fitted over them (triaxial runs at several confining
stresses; `grainlab report` fits it and writes mohr_coulomb.json next to the
page before it runs this script). The page works offline:
inline CSS, no JavaScript, relative links to the PNGs written next to it. The figures mirror He, Zheng & Schaefer (2021),
"Simulating shearing behavior of realistic granular soils using physics
engine", Figs. 10-17.

Input contract (what a run folder holds; SI units everywhere)
--------------------------------------------------------------
Required (the script stops with a one-line message and exit status 1 without them):

  series.csv   header row of column names, then one row of numbers per sample
               during shear ("nan" allowed). Columns are used by name; the
               first ten are always written by the engine:
                 time_s, shear_strain, horizontal_displacement_m,
                 vertical_displacement_m (cap, up = dilation = positive),
                 shear_force_N, normal_force_N, normal_stress_Pa, stress_ratio,
                 friction_angle_deg, void_ratio
               and may follow (each optional):
                 coordination_number, kinetic_energy_J, unbalanced_force_ratio,
                 inertial_number, rotation_mean_deg, rotation_band_deg,
                 coordination_number_band, fabric_psi, fabric_psi_band,
                 band_low_m, band_high_m
  run.json     {"grainlab_version", "config": {grains, material, box, specimen,
               consolidation, shear, numerics, output: {key: scalar}}, "seed",
               "grains" (count), "time_step_s", "density_scaling",
               "shear_speed_m_per_s", "mean_equivalent_diameter_m",
               "mean_roundness" (optional), "preparation": {"void_ratio" (whole
               specimen), "bulk_void_ratio" (away from the walls), "relative_density",
               "relative_density_own", "own_e_min", "own_e_max" (these three where the
               grains' own index void ratios are known), "target_void_ratio"}, "peaks":
               {"friction_angle_deg", "strain_at_peak_friction", "stress_ratio",
               "dilation_angle_deg", "strain_at_peak_dilation", "friction_is_peak",
               "dilation_is_peak" (false: the largest value lies in the last 5 % of the
               strain, no peak reached), "fabric_psi",
               "fabric_psi_band" (both optional)}, "final": {"friction_angle_deg", "dilation_angle_deg",
               "void_ratio", "contact_force_mean_N" (optional: the mean normal contact
               force, where strong force chains begin)}, "timings": {"wall_s", "steps",
               "simulated_s"}}

Optional (a figure whose input is missing is replaced by a visible
"not available: FILE missing" note):

  analysis/profile.csv       z_m, displacement_x_m, count: final mean horizontal
                             grain displacement since the start of shear per layer
  analysis/band.json         {"low_m", "high_m", "method"}: the final shear band
  analysis/fabric.json       {"all": {...}, "band": {...}}, each with "contacts",
                             "phi" (3x3), "D2" (3x3), "D4" (3x3x3x3),
                             "principal_values" (3), "psi", "normals" ([[nx, ny, nz],
                             ...]), "rose": {"z_edges", "azimuth_edges_rad",
                             "density_per_sr" (n_z x n_az)}: the rose histogram of the
                             normals (each counted as n and -n, bins uniform in n_z and
                             azimuth, so of equal solid angle), and "kanatani_grid":
                             {"theta_rad", "phi_rad", "density_per_sr" (n_theta x n_phi)}:
                             Kanatani's density sampled on that grid (theta from +z,
                             phi the azimuth from +x)
  analysis/force_chains.csv  x1_m, y1_m, z1_m, x2_m, y2_m, z2_m, force_N, strong: one
                             grain-grain contact per row, between grain centres; strong
                             is 1 for a normal force above the mean (a strong chain)
  analysis/derived.csv       shear_strain, dilation_angle_deg: the engine's dilation
                             angle (Eq. 19) at every sample of series.csv

Frames and conventions the figures assume: x is the shear direction, z is up;
heights (profile z_m, band_low_m/high_m, band.json, force-chain z) are in the
engine's world frame with the box floor at z = 0, so the shear plane (middle
of the gap) is at z = box.height / 2; the report plots heights relative to it,
as the paper does (Fig. 11). Kanatani's density is
f(n) = (1 / 4 pi) (1 + D2_ij n_i n_j + D4_ijkl n_i n_j n_k n_l), in 1/sr,
integrating to one over the sphere.

  mohr_coulomb.json          (a triaxial comparison's output folder, written there by
                             `grainlab report`, src/io/mohr_coulomb_file.h): the envelopes
                             fitted over the runs and each run's circles

The report derives no number: every value it prints or plots is read from
these files (the engine computes them: src/analysis/, also the peak rule and
the Mohr-Coulomb fit); it picks values (a peak's row, a stage's last row),
converts units for display and draws. What is left of arithmetic here is
listed in docs/outputs.md ("What the report computes").

A test this script has no figures of (config.test other than direct-shear,
oedometer and triaxial) gets a generic page: every series column against the
test's progress column (its first column after time_s) in series.png, and
run.json's group named after the test in a table.

Figures of one run: stress ratio F/N (Fig. 10a), cap vertical displacement
(Fig. 10b), horizontal displacement against height with the band (Fig. 11),
mean rotation (Fig. 13), coordination number (Fig. 14), 3D rose diagrams of
contact normals with Kanatani's density (Fig. 15), fabric factor Psi (Fig. 16),
force chains (Fig. 17); tables of inputs and peak values. Comparison: overlays
of F/N and cap displacement (Fig. 10a, b), peak friction and dilation angles
against mean roundness (Fig. 10c, d) and a table of peaks. Triaxial comparison:
q/p' and eps_v against eps_a, stress paths in p'-q, Mohr circles at the peak
and at the critical state with the fitted envelopes, a table of the fits
(phi', c', R^2, from mohr_coulomb.json) and one of the runs. Runs of different
tests are not compared, nor oedometer runs.

Output: index.html and the PNGs are (over)written in the output folder; PNGs of an earlier report that this
one does not draw are removed. At the end the
script prints the path of index.html, the figures written and the notes. Exit
status 0, or 1 with one line "report.py: error: ..." on stderr when a run
folder lacks series.csv or run.json (or they cannot be read), or when the runs
of a comparison are of different tests or are oedometer runs.
Only the Python standard library, numpy and matplotlib (Agg backend) are used.
"""

import argparse
import csv
import html
import json
import math
import os
import re
import sys
from pathlib import Path

import numpy as np
import matplotlib
import matplotlib.ticker
import matplotlib.transforms

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import cm, colors  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection  # noqa: E402

DPI = 130
ALL_COLOR, BAND_COLOR = "#1f4e9c", "#c0392b"
RUN_COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
              "#7f7f7f", "#bcbd22"]
REQUIRED_COLUMNS = ["time_s", "shear_strain", "horizontal_displacement_m", "vertical_displacement_m",
                    "shear_force_N", "normal_force_N", "normal_stress_Pa", "stress_ratio",
                    "friction_angle_deg", "void_ratio"]

# Every PNG this script may write (so stale ones from an earlier report are removed).
SINGLE_PNGS = ["stress_ratio.png", "vertical_displacement.png", "displacement_profile.png", "rotation.png",
               "coordination_number.png", "rose_diagram.png", "fabric_psi.png", "force_chains.png",
               "e_log_sigma.png", "k0.png", "constrained_modulus.png", "triaxial_curves.png", "stress_path.png",
               "series.png"]
COMPARISON_PNGS = ["stress_strain_overlay.png", "peaks_vs_roundness.png"]
TRIAXIAL_COMPARISON_PNGS = ["triaxial_overlay.png", "stress_paths.png", "mohr_circles.png"]
# What a comparison folder may hold besides index.html (both kinds: an --out folder may hold either); a direct
# shear comparison removes all of it, a triaxial one keeps mohr_coulomb.json, which grainlab report writes.
COMPARISON_OUTPUTS = COMPARISON_PNGS + TRIAXIAL_COMPARISON_PNGS + ["mohr_coulomb.json"]

plt.rcParams.update({
    "font.size": 10, "axes.titlesize": 11, "axes.labelsize": 10, "legend.fontsize": 9,
    "axes.grid": True, "grid.alpha": 0.3, "savefig.bbox": "tight", "savefig.dpi": DPI,
})


# The column each known test's series progresses along; a test not named here gets the generic report
# (generic_report), which draws every column against its first column after time_s.
PROGRESS_COLUMNS = {"direct-shear": "shear_strain", "oedometer": "stage", "triaxial": "axial_strain"}


class ReportError(Exception):
    """A fatal problem with the inputs; its message is printed as one line."""


# ---------------------------------------------------------------------------
# Reading a run folder.

def read_csv_columns(path):
    """Named float columns of a CSV file (header row, then numbers); bad or empty cells are nan."""
    with open(path, newline="") as fh:
        rows = [r for r in csv.reader(fh) if r and any(c.strip() for c in r)]
    if not rows:
        raise ValueError("empty file")
    header = [h.strip() for h in rows[0]]
    values = np.full((len(rows) - 1, len(header)), np.nan)
    for i, r in enumerate(rows[1:]):
        for j in range(min(len(r), len(header))):
            try:
                values[i, j] = float(r[j])
            except ValueError:
                pass
    return {name: values[:, j] for j, name in enumerate(header) if name}


def get(d, *keys, default=None):
    """d[k0][k1]... or default when any level is missing."""
    for k in keys:
        if not isinstance(d, dict) or k not in d or d[k] is None:
            return default
        d = d[k]
    return d


def num(x):
    """x as a float, or None when it is not a finite number."""
    try:
        v = float(x)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


class Run:
    """One run folder: its series columns, run.json and the paths of its optional files."""

    def __init__(self, folder):
        self.dir = Path(folder)
        if not self.dir.is_dir():
            raise ReportError(f"'{folder}' is not a folder: give a grainlab run folder (with series.csv and run.json)")
        for name in ("series.csv", "run.json"):
            if not (self.dir / name).is_file():
                raise ReportError(f"'{folder}' has no {name}: not a grainlab run folder "
                                  "(a run writes series.csv and run.json; run it first or check the path)")
        try:
            self.series = read_csv_columns(self.dir / "series.csv")
        except (OSError, ValueError, csv.Error) as e:
            raise ReportError(f"cannot read '{self.dir / 'series.csv'}': {e}")
        try:
            self.info = json.loads((self.dir / "run.json").read_text())
        except (OSError, ValueError) as e:
            raise ReportError(f"cannot read '{self.dir / 'run.json'}': {e}")
        if not isinstance(self.info, dict):
            raise ReportError(f"'{self.dir / 'run.json'}' is not a JSON object")
        self.test = get(self.info, "config", "test", default="direct-shear")
        first = PROGRESS_COLUMNS.get(self.test) or self.progress_column
        if first is None or first not in self.series:
            raise ReportError(f"'{self.dir / 'series.csv'}' has no {first or 'column besides time_s'}"
                              + (" column" if first else "") + f": not a grainlab {self.test} series")
        if len(self.series[first]) == 0:
            raise ReportError(f"'{self.dir / 'series.csv'}' has a header but no rows: the run has not "
                              + ("loaded" if self.test == "oedometer" else "sheared") + " yet")
        self.name = self.dir.resolve().name
        self.label = self.preset or self.name

    @property
    def progress_column(self):
        """The column a test's series progresses along: the known tests' own (PROGRESS_COLUMNS), else the first
        column that is not time_s (the engine writes the time, then the test's progress); None without one."""
        known = PROGRESS_COLUMNS.get(self.test)
        if known is not None:
            return known
        return next((c for c in self.series if c != "time_s"), None)

    @property
    def preset(self):
        return get(self.info, "config", "grains", "preset", default="")

    @property
    def sand(self):
        return get(self.info, "config", "material", "preset", default="")

    def col(self, name):
        """The named series column, or None when it is missing or all nan."""
        c = self.series.get(name)
        return None if c is None or not np.any(np.isfinite(c)) else c

    @property
    def strain_pct(self):
        return 100.0 * self.series["shear_strain"]

    def path(self, rel):
        return self.dir / rel

    @property
    def shear_plane_z(self):
        """World z of the shear plane (middle of the gap) = box height / 2, or None if unknown."""
        h = num(get(self.info, "config", "box", "height"))
        return None if h is None else 0.5 * h

    # Peak values, as the engine found and judged them (run.json "peaks"; src/analysis/peak.h).
    def peak(self, what):
        """(largest value, strain at it, whether it is a peak) of run.json's peaks for what = "friction" or
        "dilation"; (None, None, True) without them. A run written before the engine judged its peaks (no
        peaks.<what>_is_peak) has each largest value shown as its peak."""
        v = num(get(self.info, "peaks", f"{what}_angle_deg"))
        e = num(get(self.info, "peaks", f"strain_at_peak_{what}"))
        return v, e, get(self.info, "peaks", f"{what}_is_peak", default=True) is not False

    def peak_friction(self):
        return self.peak("friction")

    def peak_dilation(self):
        return self.peak("dilation")

    def peak_psi(self, band=False):
        return num(get(self.info, "peaks", "fabric_psi_band" if band else "fabric_psi"))

    def derived(self):
        """analysis/derived.csv (the engine's per-sample derived series) as columns, or None."""
        p = self.path("analysis/derived.csv")
        if not p.is_file():
            return None
        try:
            return read_csv_columns(p)
        except (OSError, ValueError, csv.Error):
            return None

    def band(self):
        """(low_m, high_m, method, source) of the final shear band, or None."""
        p = self.path("analysis/band.json")
        if p.is_file():
            try:
                b = json.loads(p.read_text())
                lo, hi = num(b.get("low_m")), num(b.get("high_m"))
                if lo is not None and hi is not None:
                    return lo, hi, str(b.get("method", "")), "analysis/band.json"
            except (OSError, ValueError, AttributeError):
                pass
        lo, hi = self.col("band_low_m"), self.col("band_high_m")
        if lo is not None and hi is not None:
            ok = np.isfinite(lo) & np.isfinite(hi)
            if np.any(ok):
                k = np.nonzero(ok)[0][-1]
                return float(lo[k]), float(hi[k]), "last sample of series.csv", "series.csv"
        return None


# The engine calls no largest value in the last 5 % of the test's strain a peak (run.json peaks.*_is_peak).
NO_PEAK = ("no peak: {what} is largest at the end of the test and may still be rising; shear further "
           "(shear.final_strain) to find its peak")


# ---------------------------------------------------------------------------
# Figure records.

class Figure:
    """One entry of the report: a PNG (or none) with its caption and notes."""

    def __init__(self, title, paper, caption=""):
        self.title, self.paper, self.caption = title, paper, caption
        self.png = None
        self.notes = []      # "not available: ..." and partial-data notes
        self.warnings = []   # consistency problems found in the data

    def missing(self, what, detail=""):
        self.notes.append(f"not available: {what} missing" + (f" ({detail})" if detail else ""))
        return self

    def save(self, fig, out_dir, name):
        fig.savefig(out_dir / name)
        plt.close(fig)
        self.png = name
        return self


def pct_axis(ax):
    ax.set_xlabel("shear strain $\\varepsilon_s = d_h / L$ (%)")
    ax.set_xlim(left=0)


def all_band_figure(run, out_dir, name, cols, ylabel, title, paper, caption):
    """Shared body of the 'all grains and shear band against strain' figures (13, 14, 16)."""
    f = Figure(title, paper, caption)
    c_all, c_band = run.col(cols[0]), run.col(cols[1])
    if c_all is None and c_band is None:
        return f.missing(f"series.csv columns {cols[0]} and {cols[1]}")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    x = run.strain_pct
    if c_all is not None:
        ax.plot(x, c_all, color=ALL_COLOR, lw=1.6, label="all grains")
    else:
        f.missing(f"series.csv column {cols[0]} (all grains)")
    if c_band is not None:
        ax.plot(x, c_band, color=BAND_COLOR, lw=1.6, ls="--", label="grains in the shear band")
    else:
        f.missing(f"series.csv column {cols[1]} (shear band)")
    pct_axis(ax)
    ax.set_ylabel(ylabel)
    ax.legend(loc="best")
    ax.set_title(title)
    return f.save(fig, out_dir, name)


# ---------------------------------------------------------------------------
# The figures of one run, one function each.

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


def fig_displacement_profile(run, out_dir):
    """Fig. 11: mean horizontal grain displacement against height, shear band shaded."""
    f = Figure("Horizontal grain displacement against height", "Fig. 11",
               "Mean horizontal displacement of the grains since the start of shear, per height layer, at the "
               "end of the test, against height above the shear plane (the middle of the gap between the box "
               "halves, z = H/2 in the engine's frame). The shaded layer is the shear band.")
    p = run.path("analysis/profile.csv")
    if not p.is_file():
        return f.missing("analysis/profile.csv")
    try:
        prof = read_csv_columns(p)
    except (OSError, ValueError, csv.Error) as e:
        f.notes.append(f"not available: analysis/profile.csv unreadable ({e})")
        return f
    lacking = [c for c in ("z_m", "displacement_x_m") if c not in prof]
    if lacking:
        return f.missing("analysis/profile.csv column " + " and ".join(lacking))
    z0 = run.shear_plane_z
    ref = 0.0 if z0 is None else z0
    ylabel = ("height above the shear plane, z − H/2 (mm)" if z0 is not None
              else "height z (mm, engine frame)")
    if z0 is None:
        f.notes.append("config.box.height missing from run.json: heights shown in the engine's frame")
    z = 1e3 * (prof["z_m"] - ref)
    ux = 1e3 * prof["displacement_x_m"]
    order = np.argsort(z)
    fig, ax = plt.subplots(figsize=(5.2, 5.0))
    band = run.band()
    if band is not None:
        lo, hi, method, source = band
        ax.axhspan(1e3 * (lo - ref), 1e3 * (hi - ref), color=BAND_COLOR, alpha=0.15,
                   label=f"shear band, {1e3 * (hi - lo):.2f} mm thick")
        f.caption += f" Band from {html.escape(source)}" + (f" ({html.escape(method)})." if method else ".")
    else:
        f.missing("analysis/band.json and series.csv band_low_m/band_high_m (no band shaded)")
    ax.plot(ux[order], z[order], "o-", color=ALL_COLOR, ms=3.5, lw=1.2, label="layer mean")
    if z0 is not None:
        ax.axhline(0, color="0.3", lw=0.8, ls=":", label="shear plane")
    ax.set_xlabel("horizontal grain displacement $u_x$ (mm)")
    ax.set_ylabel(ylabel)
    ax.legend(loc="upper left")
    ax.set_title("Horizontal displacement profile")
    return f.save(fig, out_dir, "displacement_profile.png")


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


def fig_fabric_psi(run, out_dir):
    """Fig. 16: octahedral fabric factor Psi, all grains and band, against strain."""
    f = all_band_figure(
        run, out_dir, "fabric_psi.png", ("fabric_psi", "fabric_psi_band"),
        "octahedral fabric factor $\\Psi$ (–)", "Fabric anisotropy", "Fig. 16",
        "Generalised octahedral fabric factor &Psi; = [(&phi;<sub>1</sub>&minus;&phi;<sub>2</sub>)<sup>2</sup> + "
        "(&phi;<sub>1</sub>&minus;&phi;<sub>3</sub>)<sup>2</sup> + (&phi;<sub>2</sub>&minus;&phi;<sub>3</sub>)"
        "<sup>2</sup>]<sup>1/2</sup>/&radic;2 of the principal values of the contact-normal fabric tensor "
        "(Eq. 29), for all contacts and for contacts in the shear band, against shear strain "
        "(0 = isotropic).")
    return f


# -- Fig. 15: rose diagrams -------------------------------------------------

def rose_surface(density, z_edges, az_edges):
    """The 3D rose as a closed surface r(theta, phi) = bin frequency: one vertex at the centre of
    every bin at radius = its density (plus the two poles, at the mean of the polar bins), joined
    into quads; the azimuth seam is closed. Returns X, Y, Z vertex grids and R per quad (mean of
    its corners), for colouring."""
    zc = 0.5 * (z_edges[:-1] + z_edges[1:])
    ac = 0.5 * (az_edges[:-1] + az_edges[1:])
    z = np.concatenate([[-1.0], zc, [1.0]])
    a = np.concatenate([ac, [ac[0] + 2 * math.pi]])
    r = np.vstack([np.full(len(ac), density[0].mean()), density, np.full(len(ac), density[-1].mean())])
    r = np.hstack([r, r[:, :1]])
    rho = np.sqrt(np.clip(1 - z ** 2, 0, None))[:, None]
    X, Y, Z = r * rho * np.cos(a)[None, :], r * rho * np.sin(a)[None, :], r * z[:, None]
    quad_r = 0.25 * (r[:-1, :-1] + r[1:, :-1] + r[:-1, 1:] + r[1:, 1:])
    return X, Y, Z, quad_r


def load_fabric(run, f):
    """analysis/fabric.json as {'all': {...}, 'band': {...}}, or None with a note in f."""
    p = run.path("analysis/fabric.json")
    if not p.is_file():
        f.missing("analysis/fabric.json")
        return None
    try:
        fab = json.loads(p.read_text())
    except (OSError, ValueError) as e:
        f.notes.append(f"not available: analysis/fabric.json unreadable ({e})")
        return None
    if not isinstance(fab, dict):
        f.notes.append("not available: analysis/fabric.json is not a JSON object")
        return None
    return fab


def as_array(x, shape):
    """x as a float array of the given shape, or None when it is missing or malformed."""
    try:
        a = np.asarray(x, float).reshape(shape)
    except (TypeError, ValueError):
        return None
    return a if np.all(np.isfinite(a)) else None


def fabric_set(entry, which, f):
    """The rose histogram, Kanatani grid, Psi and principal values of one set ('all' or 'band') of
    fabric.json, as the engine wrote them; None with a note when nothing can be drawn."""
    contacts = entry.get("contacts")
    if contacts == 0:
        f.notes.append(f"fabric.json '{which}': no contacts" + (f" ({entry['note']})" if entry.get("note") else ""))
        return None
    grid = entry.get("kanatani_grid") if isinstance(entry.get("kanatani_grid"), dict) else {}
    th, ph = as_array(grid.get("theta_rad"), (-1,)), as_array(grid.get("phi_rad"), (-1,))
    fk = None
    if th is not None and ph is not None:
        fk = as_array(grid.get("density_per_sr"), (len(th), len(ph)))
    if fk is None:
        f.missing(f"analysis/fabric.json '{which}' kanatani_grid")
        return None
    rose = entry.get("rose") if isinstance(entry.get("rose"), dict) else {}
    ze, ae = as_array(rose.get("z_edges"), (-1,)), as_array(rose.get("azimuth_edges_rad"), (-1,))
    hist = None
    if ze is not None and ae is not None and len(ze) > 1 and len(ae) > 1:
        dens = as_array(rose.get("density_per_sr"), (len(ze) - 1, len(ae) - 1))
        hist = None if dens is None else (dens, ze, ae)
    if hist is None:
        f.notes.append(f"fabric.json '{which}': no rose histogram, only Kanatani's density is drawn")
    T, P = np.meshgrid(th, ph, indexing="ij")
    unit = np.stack([np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)], axis=-1)
    return {"contacts": num(contacts), "unit": unit, "kanatani": fk, "hist": hist, "psi": num(entry.get("psi")),
            "principal_values": as_array(entry.get("principal_values"), (3,))}


def fig_rose(run, out_dir):
    """Fig. 15: 3D rose diagrams of contact normals (all and band) with Kanatani's surface."""
    f = Figure("Contact normals: 3D rose diagrams and Kanatani's density", "Fig. 15",
               "Spherical histograms of the contact normals at the end of the test (each normal counted as n and "
               "&minus;n, bins of equal solid angle): every face sits at a distance from the centre equal to the "
               "bin's frequency per steradian, coloured by it. The black wireframe is Kanatani's fourth-order "
               "density f(n) = (1 + D<sub>ij</sub>n<sub>i</sub>n<sub>j</sub> + "
               "D<sub>ijkl</sub>n<sub>i</sub>n<sub>j</sub>n<sub>k</sub>n<sub>l</sub>)/4&pi; (Eqs. 23-28) of the "
               "same normals; both as the engine computed them (analysis/fabric.json). An isotropic fabric is a sphere of radius 1/4&pi; = 0.080 sr<sup>&minus;1</sup>. "
               "x is the shear direction, z is up.")
    fab = load_fabric(run, f)
    if fab is None:
        return f
    sets = []
    for which, title in (("all", "all contacts"), ("band", "contacts in the shear band")):
        if not isinstance(fab.get(which), dict):
            f.missing(f"analysis/fabric.json '{which}' entry")
            continue
        s = fabric_set(fab[which], which, f)
        if s is not None:
            sets.append((which, title, s))
    if not sets:
        return f
    rmax, drawn = 0.0, []
    for which, title, st in sets:
        fk = st["kanatani"]
        if np.any(fk < 0):
            f.notes.append(f"'{which}': Kanatani's density is negative in places (drawn as 0)")
            fk = np.clip(fk, 0, None)
        hist = st["hist"]
        rmax = max(rmax, float(fk.max()), 0.0 if hist is None else float(hist[0].max()))
        drawn.append((which, title, st, fk, hist))
    rmax *= 1.05
    norm = colors.Normalize(0, rmax)
    cmap = cm.viridis
    fig = plt.figure(figsize=(5.6 * len(drawn) + 0.8, 5.8))
    fig.subplots_adjust(left=0.0, right=0.9, bottom=0.1, top=0.92, wspace=0.05)
    side = ["Left", "Right"] if len(drawn) == 2 else ["Shown"]
    for k, (which, title, s, fk, hist) in enumerate(drawn):
        ax = fig.add_subplot(1, len(drawn), k + 1, projection="3d", computed_zorder=False)
        if hist is not None:
            X, Y, Z, quad_r = rose_surface(*hist)
            ax.plot_surface(X, Y, Z, facecolors=cmap(norm(quad_r)), rstride=1, cstride=1, linewidth=0.25,
                            edgecolor=(1, 1, 1, 0.3), antialiased=True, shade=True, zorder=1)
        grid = s["unit"]
        ax.plot_wireframe(fk * grid[..., 0], fk * grid[..., 1], fk * grid[..., 2], rstride=2, cstride=3,
                          color="black", linewidth=0.4, alpha=0.6, zorder=2)
        ax.set_xlim(-rmax, rmax), ax.set_ylim(-rmax, rmax), ax.set_zlim(-rmax, rmax)
        ax.set_box_aspect((1, 1, 1), zoom=0.95)  # a sphere must look round
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_major_locator(matplotlib.ticker.MaxNLocator(4, symmetric=True))
        ax.view_init(elev=18, azim=-72)
        ax.set_xlabel("$f\\,n_x$ (sr$^{-1}$), x = shear", labelpad=2)
        ax.set_ylabel("$f\\,n_y$ (sr$^{-1}$)", labelpad=2)
        ax.set_zlabel("$f\\,n_z$ (sr$^{-1}$), z = up", labelpad=2)
        ax.tick_params(labelsize=7, pad=0)
        n_c = "contacts not given" if s["contacts"] is None else f"{s['contacts']:.0f} contacts"
        psi = "not given" if s["psi"] is None else f"{s['psi']:.3f}"
        ax.set_title(f"{title}\n$\\Psi$ = {psi}, {n_c}", fontsize=10)
        pv = ("" if s["principal_values"] is None else
              ", principal values of &phi;<sub>ij</sub> " + " / ".join(f"{v:.3f}" for v in s["principal_values"]))
        f.caption += f" {side[k]}: {title} ({n_c}, &Psi; = {psi}{pv})."
    if any(hist is not None for *_, hist in drawn):
        cb = fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=fig.axes, shrink=0.6, pad=0.04)
        cb.set_label("frequency of contact normals per solid angle (sr$^{-1}$)")
    return f.save(fig, out_dir, "rose_diagram.png")


# -- Fig. 17: force chains ----------------------------------------------------

def fig_force_chains(run, out_dir):
    """Fig. 17: contact-force segments, side view (x-z) and 3D, strong chains emphasised."""
    f = Figure("Force chains", "Fig. 17",
               "Grain-grain contact forces at the end of the test, each drawn as a segment between the two "
               "grain centres. Contacts carrying more than the mean force (strong chains, as the engine marks "
               "them in analysis/force_chains.csv) are coloured and "
               "thickened by force; the weaker ones are thin and grey. Left: side view, projected on the x-z "
               "plane (x = shear direction); right: 3D view.")
    p = run.path("analysis/force_chains.csv")
    if not p.is_file():
        return f.missing("analysis/force_chains.csv")
    try:
        fc = read_csv_columns(p)
    except (OSError, ValueError, csv.Error) as e:
        f.notes.append(f"not available: analysis/force_chains.csv unreadable ({e})")
        return f
    need = ["x1_m", "y1_m", "z1_m", "x2_m", "y2_m", "z2_m", "force_N"]
    lacking = [c for c in need if c not in fc]
    if lacking:
        return f.missing("analysis/force_chains.csv columns " + ", ".join(lacking))
    if "strong" not in fc:
        f.missing("analysis/force_chains.csv column strong", "every contact drawn as weak")
    a = np.column_stack([fc[c] for c in need] + [fc.get("strong", np.zeros(len(fc["force_N"])))])
    a = a[np.all(np.isfinite(a), axis=1)]
    if len(a) == 0:
        f.notes.append("not available: analysis/force_chains.csv has no contacts")
        return f
    p1, p2, force = 1e3 * a[:, 0:3], 1e3 * a[:, 3:6], np.abs(a[:, 6])
    order = np.argsort(force)
    p1, p2, force, strong = p1[order], p2[order], force[order], a[order, 7] > 0.5
    fmax = float(force.max())
    mean = num(get(run.info, "final", "contact_force_mean_N"))
    if mean is None:
        f.missing("run.json final.contact_force_mean_N", "colour scale from the weakest strong contact")
        mean = float(force[strong].min()) if np.any(strong) else fmax
    norm = colors.Normalize(mean, fmax if fmax > mean else mean * 1.0001)
    cmap = colors.LinearSegmentedColormap.from_list("chains", cm.inferno_r(np.linspace(0.2, 0.95, 256)))
    t = np.clip((force - mean) / max(fmax - mean, 1e-300), 0, 1)  # 0 at the mean force, 1 at the largest
    crowd = min(1.0, math.sqrt(2000.0 / max(1, int(strong.sum()))))  # thinner lines when there are many
    width = crowd * (0.5 + 3.5 * np.sqrt(t))
    rgba = cmap(norm(force))
    rgba[:, 3] = 0.45 + 0.55 * np.sqrt(t)  # the weakest strong chains fade a little
    weak_max = 30000
    weak = np.nonzero(~strong)[0]
    if len(weak) > weak_max:
        weak = np.random.default_rng(0).choice(weak, weak_max, replace=False)
        f.notes.append(f"{weak_max} of the {int(np.sum(~strong))} weak contacts drawn")

    fig = plt.figure(figsize=(13.5, 5.4))
    gs = fig.add_gridspec(1, 2, width_ratios=[1.0, 1.2], wspace=0.08)
    ax = fig.add_subplot(gs[0, 0])
    ref = run.shear_plane_z
    zr = 0.0 if ref is None else 1e3 * ref
    seg = lambda idx, i, j: np.stack([np.column_stack([p1[idx, i], p1[idx, j] - (zr if j == 2 else 0)]),
                                      np.column_stack([p2[idx, i], p2[idx, j] - (zr if j == 2 else 0)])], axis=1)
    ax.add_collection(LineCollection(seg(weak, 0, 2), colors="0.72", linewidths=0.4, alpha=0.6))
    s_idx = np.nonzero(strong)[0]
    ax.add_collection(LineCollection(seg(s_idx, 0, 2), colors=rgba[s_idx], linewidths=width[s_idx]))
    band = run.band()
    if band is not None:
        for zb in band[:2]:
            ax.axhline(1e3 * zb - zr, color=BAND_COLOR, lw=0.9, ls="--")
        ax.plot([], [], color=BAND_COLOR, lw=0.9, ls="--", label="shear band limits")
    if ref is not None:
        ax.axhline(0, color="0.3", lw=0.8, ls=":", label="shear plane")
    ax.plot([], [], color="0.72", lw=0.6, label=f"weak: force ≤ mean ({mean:.3g} N)")
    ax.plot([], [], color=cmap(0.7), lw=2.5, label="strong: force > mean")
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("x, shear direction (mm)")
    ax.set_ylabel("height above the shear plane, z − H/2 (mm)" if ref is not None else "z (mm)")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, fontsize=8, frameon=False)
    ax.set_title("side view (x-z projection)")
    ax.grid(False)

    ax3 = fig.add_subplot(gs[0, 1], projection="3d", computed_zorder=False)
    shift = np.array([0.0, 0.0, zr])  # same heights as the side view
    q1, q2 = p1 - shift, p2 - shift
    seg3 = lambda idx: np.stack([q1[idx], q2[idx]], axis=1)
    ax3.add_collection3d(Line3DCollection(seg3(weak), colors="0.65", linewidths=0.3, alpha=0.4))
    ax3.add_collection3d(Line3DCollection(seg3(s_idx), colors=rgba[s_idx],
                                          linewidths=0.7 * width[s_idx]))
    lo, hi = np.minimum(q1.min(0), q2.min(0)), np.maximum(q1.max(0), q2.max(0))
    ax3.set_xlim(lo[0], hi[0]), ax3.set_ylim(lo[1], hi[1]), ax3.set_zlim(lo[2], hi[2])
    ax3.set_box_aspect(tuple(np.maximum(hi - lo, 1e-9)), zoom=1.1)
    ax3.view_init(elev=16, azim=-62)
    ax3.set_xlabel("x, shear (mm)"), ax3.set_ylabel("y (mm)"), ax3.set_zlabel("z − H/2 (mm)" if ref is not None else "z (mm)")
    ax3.tick_params(labelsize=7, pad=0)
    ax3.set_title("3D view")
    cb = fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax3, shrink=0.7, pad=0.16)
    cb.set_label("contact force of strong chains (N)")
    f.caption += (f" {len(force)} contacts; mean force {mean:.3g} N, maximum {fmax:.3g} N, "
                  f"{int(strong.sum())} strong.")
    return f.save(fig, out_dir, "force_chains.png")


# ---------------------------------------------------------------------------
# Tables.

def fmt(v, spec=".3g", unit=""):
    v = num(v)
    if v is None:
        return "&mdash;"
    return f"{v:{spec}}" + (f" {unit}" if unit else "")


def fmt_duration(s):
    s = num(s)
    if s is None:
        return "&mdash;"
    h, rem = divmod(int(round(s)), 3600)
    m, sec = divmod(rem, 60)
    return f"{s:.0f} s ({h}:{m:02d}:{sec:02d})"


def esc(x):
    return html.escape(str(x)) if x not in (None, "") else "&mdash;"


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


def table_html(rows, caption):
    body = "\n".join(f"<tr><th>{k}</th><td>{v}</td></tr>" for k, v in rows)
    return f'<table class="kv"><caption>{caption}</caption>\n{body}\n</table>'


# ---------------------------------------------------------------------------
# Comparison figures.

def run_colors(runs):
    return {id(r): RUN_COLORS[k % len(RUN_COLORS)] for k, r in enumerate(runs)}


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


# ---------------------------------------------------------------------------
# The page.

CSS = """
body { font-family: system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; margin: 2em auto;
       max-width: 1100px; padding: 0 1em; color: #222; line-height: 1.45; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; } h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; margin-top: 2em; }
.sub { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 0.8em 0 1.2em; font-size: 0.92em; }
caption { text-align: left; font-weight: 600; padding-bottom: 0.3em; }
table.kv th { text-align: left; font-weight: normal; color: #444; padding: 0.2em 1.2em 0.2em 0; }
table.kv td { padding: 0.2em 0; }
table.grid th, table.grid td { border: 1px solid #ccc; padding: 0.25em 0.5em; text-align: right; }
table.grid th { background: #f3f3f3; } table.grid td:first-child, table.grid td:nth-child(2),
table.grid td:nth-child(3) { text-align: left; }
.tables { display: flex; flex-wrap: wrap; gap: 3em; }
figure { margin: 1.5em 0 2.2em; } figure img { max-width: 100%; border: 1px solid #eee; }
figcaption { font-size: 0.92em; color: #333; max-width: 900px; }
.note { background: #fff7e0; border-left: 4px solid #e0a800; padding: 0.4em 0.8em; margin: 0.4em 0; font-size: 0.92em; }
.warn { background: #fdecea; border-left: 4px solid #c0392b; padding: 0.4em 0.8em; margin: 0.4em 0; font-size: 0.92em; }
footer { color: #777; font-size: 0.85em; margin-top: 3em; }
"""


def figure_html(f):
    parts = [f'<figure id="{html.escape(Path(f.png).stem) if f.png else ""}">' if f.png else "<figure>"]
    parts.append(f"<h3>{html.escape(f.title)} <small>(cf. paper {f.paper})</small></h3>")
    for w in f.warnings:
        parts.append(f'<div class="warn">warning: {w}</div>')
    for n in f.notes:
        parts.append(f'<div class="note">{html.escape(n)}</div>')
    if f.png:
        parts.append(f'<a href="{html.escape(f.png)}"><img src="{html.escape(f.png)}" alt="{html.escape(f.title)}"></a>')
        source = (f"Mirrors {f.paper} of He, Zheng &amp; Schaefer (2021)." if f.paper.startswith("Fig.")
                  else f"Cf. {f.paper}.")
        parts.append(f"<figcaption>{source} {f.caption}</figcaption>")
    parts.append("</figure>")
    return "\n".join(parts)


def write_page(out_dir, title, subtitle, blocks):
    page = (f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n<title>{html.escape(title)}</title>\n'
            f"<style>{CSS}</style>\n</head>\n<body>\n<h1>{html.escape(title)}</h1>\n<p class=\"sub\">{subtitle}</p>\n"
            + "\n".join(blocks) +
            "\n<footer>Written by grainlab scripts/report.py. Figures follow He, Zheng &amp; Schaefer (2021), "
            "<i>Simulating shearing behavior of realistic granular soils using physics engine</i>, Figs. 10-17. "
            "SI units; strains in percent.</footer>\n</body>\n</html>\n")
    path = out_dir / "index.html"
    tmp = out_dir / ".index.html.tmp"
    tmp.write_text(page, encoding="utf-8")
    os.replace(tmp, path)
    return path


def prepare_out(out_dir, names):
    out_dir.mkdir(parents=True, exist_ok=True)
    for n in names:  # stale figures of an earlier report would otherwise linger unlinked
        (out_dir / n).unlink(missing_ok=True)


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


# ---------------------------------------------------------------------------
# Comparing triaxial runs at several confining stresses: overlays, stress
# paths, Mohr circles and the Mohr-Coulomb envelope fitted over the runs.
#
# Each run gives two circles: at the peak and at the critical state. The
# engine computes them and fits the envelopes (src/analysis/mohr_coulomb.h):
# `grainlab report` writes mohr_coulomb.json next to the comparison's page
# (src/io/mohr_coulomb_file.h) before it runs this script, which reads and
# draws it. Run alone on triaxial runs, the script has no fit to show and
# says so.

def triaxial_sigma3(run):
    """sigma_3 of the run (Pa): the cell pressure its sides' servos held, config.consolidation.normal_stress."""
    return num(get(run.info, "config", "consolidation", "normal_stress"))


def tidy(x):
    """x without a minus sign on a value that rounds to zero (a fitted c' of -1e-14 Pa is 0.00 kPa)."""
    return round(x, 9) + 0.0


# What mohr_coulomb.json lacks when this script was run without grainlab report.
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


def run_link(r, out_dir):
    report = r.dir / "report" / "index.html"
    name = esc(r.name)
    if report.is_file():
        name = f'<a href="{html.escape(Path(os.path.relpath(report, out_dir)).as_posix())}">{name}</a>'
    return name


def grid_html(head, rows, caption):
    th = "".join(f"<th>{h}</th>" for h in head)
    body = "\n".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows)
    return f'<table class="grid"><caption>{caption}</caption>\n<tr>{th}</tr>\n{body}\n</table>'


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



# ---------------------------------------------------------------------------
# A lab test this script has no figures of: every series column against the
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


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Write an HTML report with PNG figures for one grainlab run (direct shear: paper Figs. 10-17; "
                    "oedometer; triaxial), or a comparison report for several direct shear runs or several "
                    "triaxial runs (Mohr circles and a c', phi' fit).")
    ap.add_argument("runs", nargs="+", metavar="RUN_DIR", help="run folder(s) holding series.csv and run.json")
    ap.add_argument("--out", metavar="DIR", help="where to write index.html and the PNGs (default: RUN_DIR/report "
                    "for one run, RUN_DIR/../comparison/report for several, after the first run)")
    a = ap.parse_args(argv)
    try:
        runs = [Run(d) for d in a.runs]
        disambiguate_labels(runs)
        if a.out:
            out_dir = Path(a.out)
        elif len(runs) == 1:
            out_dir = runs[0].dir / "report"
        else:
            out_dir = runs[0].dir.resolve().parent / "comparison" / "report"
        with np.errstate(invalid="ignore", divide="ignore"):
            if len(runs) == 1:
                page, figs = single_report(runs[0], out_dir)
            else:
                page, figs = comparison_report(runs, out_dir)
    except ReportError as e:
        print(f"report.py: error: {e}", file=sys.stderr)
        return 1
    written = [f.png for f in figs if f.png]
    print(f"report: {page.resolve()}")
    print(f"figures written ({len(written)}): " + (", ".join(written) if written else "none"))
    for f in figs:
        for n in f.notes:
            print(f"  {f.paper}: {n}")
        for w in f.warnings:
            print(f"  {f.paper}: warning: {html.unescape(re.sub('<[^>]+>', '', w))}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
