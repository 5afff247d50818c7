"""grainlab.report: the run report, HTML and PNG figures for direct shear runs (paper Figs. 10-17), oedometer and
triaxial runs, any other lab test (every series column against its progress), and comparisons of direct
shear runs or of triaxial runs (Mohr circles, c' and phi').

Usage (Debian's Python, which has matplotlib and numpy; `grainlab report` takes the same arguments
and runs this package from its own copy, so the binary alone writes reports):

    python3 -m grainlab.report RUN_DIR                 # -> RUN_DIR/report/index.html
    python3 -m grainlab.report RUN_A RUN_B [...]       # -> RUN_A/../comparison/report/index.html
    python3 -m grainlab.report RUN_DIR [...] --out DIR # -> DIR/index.html
    python3 -m grainlab.report.study STUDY_DIR [--out DIR]  # the four-sand study (study.py)

From Python: grainlab.Run(folder).report(), or write_report(folders, out) here.
One module per figure kind: curves, dilation, profile, fabric, force_chains (one direct shear run),
oedometer, triaxial, generic (any other test), comparison and triaxial_comparison (several runs),
study (bench/study_four_sands); reading (the run folder), plotting (figure plumbing), tables,
html_page (the page) and reports (which page a set of runs gets); cli is the command line.

One run folder gives a report of that run; several give a comparison report
that overlays their curves and tabulates their peaks against their mean grain
roundness (direct shear), or their curves, stress paths, Mohr circles and the
Mohr-Coulomb envelope fitted over them (triaxial runs at several confining
stresses; `grainlab report` fits it and writes mohr_coulomb.json next to the
page before it runs this package). The page works offline:
inline CSS, no JavaScript, relative links to the PNGs written next to it. The figures mirror He, Zheng & Schaefer (2021),
"Simulating shearing behavior of realistic granular soils using physics
engine", Figs. 10-17.

Input contract (what a run folder holds; SI units everywhere)
--------------------------------------------------------------
Required (the report stops with a one-line message and exit status 1 without them):

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

A test this report has no figures of (config.test other than direct-shear,
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
command line prints the path of index.html, the figures written and the notes. Exit
status 0, or 1 with one line "grainlab report: error: ..." on stderr when a run
folder lacks series.csv or run.json (or they cannot be read), or when the runs
of a comparison are of different tests or are oedometer runs.
Only the Python standard library, numpy and matplotlib (Agg backend) are used.
"""

from .reading import ReportError, Run


def write_report(folders, out=None):
    """The report of one run folder, or the comparison of several, written to `out` (default: RUN_DIR/report,
    or RUN_A/../comparison/report): (path of index.html, the figures' records). Raises ReportError on a folder
    that is not a run folder or runs that cannot be compared. matplotlib is imported here, not before."""
    from .reports import write_report as write
    return write(folders, out)


__all__ = ["ReportError", "Run", "write_report"]
