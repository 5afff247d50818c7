#!/usr/bin/env bash
# Tests the report, the Python package grainlab.report (python/grainlab/report/),
# on fabricated run folders (scripts/make_fake_run.py): the package as the
# grainlab binary embeds it (`grainlab report --write-package`, checked equal to
# the source), run with `python3 -m grainlab.report`, and `grainlab report`.
# Exits non-zero on the first failure. Needs Debian's python3 with matplotlib
# and numpy (override with PY=/path/to/python3) and the grainlab binary
# (GRAINLAB=/path/to/grainlab; ctest sets it; default build/grainlab).
#
#   bash scripts/test_report.sh
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
PY="${PY:-/usr/bin/python3}"
GRAINLAB="${GRAINLAB:-$here/../build/grainlab}"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/test_report.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "ok: $*"; }

# The package as the binary embeds it, which must be the source's.
[ -x "$GRAINLAB" ] || fail "no grainlab binary at $GRAINLAB (build it, or set GRAINLAB=/path/to/grainlab)"
"$GRAINLAB" report --write-package "$tmp/pkg" >/dev/null || fail "grainlab report --write-package failed"
diff -r -x __pycache__ "$here/../python/grainlab/report" "$tmp/pkg/grainlab/report" >&2 \
  || fail "$GRAINLAB embeds another grainlab.report than python/grainlab/report (above): rebuild it"
pass "grainlab report --write-package writes python/grainlab/report as it is"
# python3 -m grainlab.report ARGS (and report_study: -m grainlab.report.study) from that copy.
report() { PYTHONPATH="$tmp/pkg" PYTHONDONTWRITEBYTECODE=1 "$PY" -m grainlab.report "$@"; }
report_study() { PYTHONPATH="$tmp/pkg" PYTHONDONTWRITEBYTECODE=1 "$PY" -m grainlab.report.study "$@"; }

# A valid PNG starts with the 8 bytes 89 50 4E 47 0D 0A 1A 0A.
is_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; }

# check_report DIR PNG...: DIR/index.html exists, links every PNG named, each
# of which exists and is a PNG; and every PNG the page links exists too.
check_report() {
  local dir="$1"; shift
  [ -s "$dir/index.html" ] || fail "$dir/index.html missing or empty"
  for png in "$@"; do
    grep -q "src=\"$png\"" "$dir/index.html" || fail "$dir/index.html does not show $png"
    grep -q "href=\"$png\"" "$dir/index.html" || fail "$dir/index.html does not link $png"
    [ -f "$dir/$png" ] || fail "$dir/$png missing"
    is_png "$dir/$png" || fail "$dir/$png is not a PNG"
  done
  local linked
  linked="$(grep -o 'src="[^"]*"' "$dir/index.html" | sed 's/^src="//; s/"$//')"
  for png in $linked; do
    case "$png" in http*|/*) fail "$dir/index.html links $png: links must be relative" ;; esac
    [ -f "$dir/$png" ] || fail "$dir/index.html links $png, which does not exist"
    is_png "$dir/$png" || fail "$dir/$png (linked) is not a PNG"
  done
  if grep -qiE '<(script|link)[ >]' "$dir/index.html"; then fail "$dir/index.html loads external CSS or JS"; fi
}

single_pngs=(stress_ratio.png vertical_displacement.png displacement_profile.png rotation.png
             coordination_number.png rose_diagram.png fabric_psi.png force_chains.png)
comparison_pngs=(stress_strain_overlay.png peaks_vs_roundness.png)

# --- two fake runs ---------------------------------------------------------------
"$PY" "$here/make_fake_run.py" "$tmp/runs/angular" --preset angular --seed 1 >/dev/null
"$PY" "$here/make_fake_run.py" "$tmp/runs/beads" --preset glass-beads --seed 2 >/dev/null
for f in series.csv run.json analysis/profile.csv analysis/band.json analysis/fabric.json analysis/force_chains.csv \
         analysis/derived.csv; do
  [ -f "$tmp/runs/angular/$f" ] || fail "make_fake_run.py did not write $f"
done
pass "make_fake_run.py writes every file of the contract"

# --- one run -----------------------------------------------------------------------
out="$(report "$tmp/runs/angular")" || fail "grainlab.report failed on a complete run"
check_report "$tmp/runs/angular/report" "${single_pngs[@]}"
# The page's text is the one checked in (written by scripts/report.py before the report became the package
# grainlab.report, its footer aside): make_fake_run.py is seeded, the page holds the run folder's path.
[ "$(sed "s|$(cd "$tmp/runs/angular" && pwd -P)|{RUN}|g" "$tmp/runs/angular/report/index.html")" \
  = "$(cat "$here/../tests/data/report/angular_index.html")" ] \
  || fail "the page of runs/angular differs from tests/data/report/angular_index.html: $(diff <(sed \
     "s|$(cd "$tmp/runs/angular" && pwd -P)|{RUN}|g" "$tmp/runs/angular/report/index.html") \
     "$here/../tests/data/report/angular_index.html" | head -5)"
grep -q "index.html" <<<"$out" || fail "grainlab.report did not print the path of index.html"
for png in "${single_pngs[@]}"; do grep -q "$png" <<<"$out" || fail "grainlab.report did not list $png"; done
if grep -q "not available" "$tmp/runs/angular/report/index.html"; then
  fail "a complete run's report says something is not available"
fi
if grep -q 'class="warn"' "$tmp/runs/angular/report/index.html"; then
  fail "a consistent fake run's report has a warning"
fi
for fig in "Fig. 10a" "Fig. 10b" "Fig. 11" "Fig. 13" "Fig. 14" "Fig. 15" "Fig. 16" "Fig. 17"; do
  grep -q "$fig" "$tmp/runs/angular/report/index.html" || fail "no caption names $fig"
done
grep -q "peak friction angle" "$tmp/runs/angular/report/index.html" || fail "no table of peaks"
pass "single-run report: index.html and its 8 PNGs"

# Both void ratios are shown, and D_r says which one (and which e_min/e_max) it is on.
page="$tmp/runs/angular/report/index.html"
grep -q "void ratio after preparation, whole specimen e" "$page" || fail "no whole-specimen void ratio row"
grep -q "void ratio after preparation, bulk e (away from the walls)" "$page" || fail "no bulk void ratio row"
grep -q "relative density D<sub>r</sub>, on the whole specimen e</th><td>[0-9.]* % (the lab&#x27;s\|relative density D<sub>r</sub>, on the whole specimen e</th><td>[0-9.]* % (the lab's" "$page" \
  || fail "D_r on the lab's indices does not say it is on the whole specimen e"
cp -r "$tmp/runs/angular" "$tmp/runs/own"
rm -rf "$tmp/runs/own/report"
"$PY" - "$tmp/runs/own/run.json" <<'PYEOF'
import json, sys
p = sys.argv[1]
j = json.load(open(p))
j["preparation"].update({"void_ratio": 0.5292, "bulk_void_ratio": 0.432, "relative_density": 0.922,
                         "relative_density_own": 0.922, "own_e_min": 0.41, "own_e_max": 0.67})
json.dump(j, open(p, "w"))
PYEOF
report "$tmp/runs/own" >/dev/null || fail "grainlab.report failed on a run prepared on its own indices"
grep -q "on the bulk e</th><td>92.2 % (the grains&#x27; own e<sub>min</sub> / e<sub>max</sub> 0.410 / 0.670)\|on the bulk e</th><td>92.2 % (the grains' own e<sub>min</sub> / e<sub>max</sub> 0.410 / 0.670)" \
  "$tmp/runs/own/report/index.html" || fail "D_r on the own indices does not say it is on the bulk e"
pass "results table: whole and bulk void ratios, and the one D_r is on"

# --- both runs: comparison in the first run's sibling folder -----------------------
report "$tmp/runs/angular" "$tmp/runs/beads" >/dev/null || fail "comparison report failed"
check_report "$tmp/runs/comparison/report" "${comparison_pngs[@]}"
grep -q "angular" "$tmp/runs/comparison/report/index.html" || fail "comparison table lacks the angular run"
grep -q "glass-beads" "$tmp/runs/comparison/report/index.html" || fail "comparison table lacks the glass-beads run"
pass "comparison report: index.html and its 2 PNGs in runs/comparison/report"

# --- --out, and a comparison without roundness --------------------------------------
"$PY" "$here/make_fake_run.py" "$tmp/runs/noround" --no-roundness >/dev/null
report "$tmp/runs/noround" "$tmp/runs/beads" --out "$tmp/cmp" >/dev/null || fail "--out failed"
check_report "$tmp/cmp" stress_strain_overlay.png peaks_vs_roundness.png
grep -q "not available: run.json mean_roundness missing" "$tmp/cmp/index.html" \
  || fail "a run without mean_roundness is not noted"
report "$tmp/runs/noround" "$tmp/runs/noround" --out "$tmp/cmp0" >/dev/null || fail "comparison without roundness failed"
check_report "$tmp/cmp0" stress_strain_overlay.png
[ ! -e "$tmp/cmp0/peaks_vs_roundness.png" ] || fail "scatter drawn although no run has a mean roundness"
grep -q "not available: run.json mean_roundness missing" "$tmp/cmp0/index.html" || fail "missing scatter not noted"
pass "--out, and the roundness scatter skipped with a note"

# --- the report reads the engine's numbers and derives none ------------------------
# No fitting, peak finding, tensors, eigenvalues or histograms in grainlab.report: those are src/analysis/'s
# (the Mohr-Coulomb fit over several triaxial runs too: grainlab report writes mohr_coulomb.json).
if grep -nE "einsum|polyfit|eigvalsh|linalg|histogram2d|arctan2|argmax|asin|def (kanatani|octahedral|dilation_angle|rose_histogram|pick_peak|mohr_coulomb_fit)" \
    "$here/../python/grainlab/report/"*.py; then
  fail "grainlab.report derives a number the engine computes (the lines above)"
fi
# Without the engine's Kanatani grid and dilation angle the report says so instead of computing them.
cp -r "$tmp/runs/angular" "$tmp/runs/nogrid"
rm -rf "$tmp/runs/nogrid/report" "$tmp/runs/nogrid/analysis/derived.csv"
"$PY" - "$tmp/runs/nogrid/analysis/fabric.json" <<'PYEOF'
import json, sys
p = sys.argv[1]
fab = json.load(open(p))
for which in ("all", "band"):
    del fab[which]["kanatani_grid"]
json.dump(fab, open(p, "w"))
PYEOF
report "$tmp/runs/nogrid" >/dev/null || fail "grainlab.report failed without kanatani_grid"
page="$tmp/runs/nogrid/report/index.html"
grep -q "not available: analysis/fabric.json &#x27;all&#x27; kanatani_grid missing" "$page" \
  || grep -q "not available: analysis/fabric.json 'all' kanatani_grid missing" "$page" \
  || fail "a fabric.json without kanatani_grid is not noted"
[ ! -e "$tmp/runs/nogrid/report/rose_diagram.png" ] || fail "rose diagram drawn without the engine's Kanatani grid"
grep -q "not available: analysis/derived.csv column dilation_angle_deg missing" "$page" \
  || fail "a run without analysis/derived.csv is not noted"
pass "the report reads the engine's numbers: no Kanatani, Psi, dilation or fits of its own"

# --- a run without analysis/ --------------------------------------------------------
cp -r "$tmp/runs/angular" "$tmp/runs/bare"
rm -rf "$tmp/runs/bare/analysis" "$tmp/runs/bare/report"
report "$tmp/runs/bare" >/dev/null || fail "grainlab.report failed on a run without analysis/"
page="$tmp/runs/bare/report/index.html"
check_report "$tmp/runs/bare/report" stress_ratio.png vertical_displacement.png rotation.png \
  coordination_number.png fabric_psi.png
for f in analysis/profile.csv analysis/fabric.json analysis/force_chains.csv; do
  grep -q "not available: $f missing" "$page" || fail "no 'not available: $f missing' note"
done
for png in displacement_profile.png rose_diagram.png force_chains.png; do
  [ ! -e "$tmp/runs/bare/report/$png" ] || fail "$png written without its input"
done
pass "run without analysis/: report with 'not available' notes"

# --- the minimal run: no analysis files nor analysis columns ------------------------
"$PY" "$here/make_fake_run.py" "$tmp/runs/minimal" --no-analysis >/dev/null
report "$tmp/runs/minimal" >/dev/null || fail "grainlab.report failed on a minimal run"
check_report "$tmp/runs/minimal/report" stress_ratio.png vertical_displacement.png
grep -q "not available: series.csv columns rotation_mean_deg and rotation_band_deg missing" \
  "$tmp/runs/minimal/report/index.html" || fail "missing rotation columns not noted"
pass "minimal run (series.csv with the engine's columns only)"

# --- refusals ---------------------------------------------------------------------
mkdir -p "$tmp/runs/empty"
cp "$tmp/runs/angular/run.json" "$tmp/runs/empty/"
set +e
msg="$(report "$tmp/runs/empty" 2>&1 >/dev/null)"; rc=$?
set -e
[ "$rc" -ne 0 ] || fail "grainlab.report accepted a folder without series.csv"
[ "$(printf '%s\n' "$msg" | wc -l)" -eq 1 ] || fail "the refusal is not one line: $msg"
grep -q "series.csv" <<<"$msg" || fail "the refusal does not name series.csv: $msg"
[ ! -e "$tmp/runs/empty/report" ] || fail "a refused folder got a report folder"
pass "refuses a folder without series.csv: $msg"

cp "$tmp/runs/angular/series.csv" "$tmp/runs/empty/"; rm "$tmp/runs/empty/run.json"
set +e
msg="$(report "$tmp/runs/empty" 2>&1 >/dev/null)"; rc=$?
set -e
[ "$rc" -ne 0 ] && grep -q "run.json" <<<"$msg" || fail "a folder without run.json was not refused clearly: $msg"
pass "refuses a folder without run.json: $msg"

# --- oedometer: stages and a constant rate of strain --------------------------------
oedometer_pngs=(e_log_sigma.png k0.png constrained_modulus.png)
for loading in stages constant-rate; do
  "$PY" "$here/make_fake_run.py" "$tmp/oed/$loading" --test oedometer --loading "$loading" >/dev/null \
    || fail "make_fake_run.py --test oedometer --loading $loading failed"
  report "$tmp/oed/$loading" >/dev/null || fail "grainlab.report failed on an oedometer run ($loading)"
  check_report "$tmp/oed/$loading/report" "${oedometer_pngs[@]}"
  if grep -q "not available" "$tmp/oed/$loading/report/index.html"; then
    fail "the oedometer report ($loading) says something is not available"
  fi
done
# Seven stages (consolidation and six); at a constant rate many rows, of which the stages' ends are seven.
grep -q "<td>7 / 7</td>" "$tmp/oed/stages/report/index.html" || fail "the staged oedometer report does not count 7 stages in 7 rows"
rows="$(($(wc -l < "$tmp/oed/constant-rate/series.csv") - 1))"
[ "$rows" -gt 50 ] || fail "the fake constant-rate oedometer has only $rows rows"
grep -q "<td>7 / $rows</td>" "$tmp/oed/constant-rate/report/index.html" \
  || fail "the constant-rate oedometer report does not find the 7 stages' ends among its $rows rows"
grep -q "constant rate of strain" "$tmp/oed/constant-rate/report/index.html" \
  || fail "the constant-rate oedometer report does not say how it was loaded"
pass "oedometer reports: stages and a constant rate of strain, each stage's end found"

# --- triaxial: one run, a comparison with Mohr circles, refusals --------------------
# Three fake runs at 50, 100 and 200 kPa whose peak lies on tau = 5 kPa + sigma' tan 34 deg and whose
# critical state lies on tau = sigma' tan 31 deg (make_fake_run.py builds q/p' for them).
for s3 in 50 100 200; do
  "$PY" "$here/make_fake_run.py" "$tmp/tx/s$s3" --test triaxial --sigma3 "$s3" --phi 34 --cohesion 5 \
    --phi-cs 31 --cohesion-cs 0 --seed "$s3" >/dev/null || fail "make_fake_run.py --test triaxial failed"
done
"$PY" - "$tmp/tx/s100" <<'PYEOF' || fail "the fake triaxial run does not have the engine's columns and run.json keys"
import csv, json, sys
d = sys.argv[1]
cols = next(csv.reader(open(d + "/series.csv")))
# src/lab/triaxial.cpp triaxial_series_columns()
want = ["time_s", "axial_strain", "volumetric_strain", "axial_stress_Pa", "cell_pressure_Pa", "deviator_stress_Pa",
        "mean_stress_Pa", "stress_ratio", "side_stress_error", "void_ratio", "coordination_number",
        "kinetic_energy_J", "unbalanced_force_ratio", "inertial_number"]
assert cols == want, cols
j = json.load(open(d + "/run.json"))
assert j["config"]["test"] == "triaxial" and j["config"]["consolidation"]["normal_stress"] == 100e3
assert set(j["triaxial"]) == {"void_ratio_at_shear", "peak_stress_ratio", "axial_strain_at_peak",
                              "peak_friction_angle_deg", "critical_stress_ratio", "critical_friction_angle_deg",
                              "peak_dilatancy_angle_deg", "e50_Pa", "final_void_ratio"}, j["triaxial"]
PYEOF
report "$tmp/tx/s100" >/dev/null || fail "grainlab.report failed on a triaxial run"
check_report "$tmp/tx/s100/report" triaxial_curves.png stress_path.png
if grep -q "not available" "$tmp/tx/s100/report/index.html"; then fail "a complete triaxial run's report misses something"; fi
grep -q "grainlab triaxial report" "$tmp/tx/s100/report/index.html" || fail "the triaxial run got another test's report"
pass "single triaxial run: index.html with triaxial_curves.png and stress_path.png"

# The comparison by grainlab report, which fits the envelopes (mohr_coulomb.json) and runs grainlab.report.
export GRAINLAB_PYTHON="$PY"
# Given out of order: the page sorts them by sigma_3.
out="$("$GRAINLAB" report "$tmp/tx/s200" "$tmp/tx/s50" "$tmp/tx/s100")" || fail "triaxial comparison failed: $out"
cmp_dir="$tmp/tx/comparison/report"
check_report "$cmp_dir" triaxial_overlay.png stress_paths.png mohr_circles.png
for png in stress_strain_overlay.png peaks_vs_roundness.png; do
  [ ! -e "$cmp_dir/$png" ] || fail "the triaxial comparison drew the direct shear $png"
done
if grep -q "not available" "$cmp_dir/index.html"; then fail "a complete triaxial comparison misses something"; fi
[ -s "$cmp_dir/mohr_coulomb.json" ] || fail "no mohr_coulomb.json next to the comparison's index.html"
"$PY" - "$cmp_dir/mohr_coulomb.json" <<'PYEOF' || fail "the Mohr-Coulomb fit does not recover the fake runs' phi' and c'"
import json, sys
m = json.load(open(sys.argv[1]))
for env, phi, c_kpa in (("peak", 34.0, 5.0), ("critical_state", 31.0, 0.0)):
    f = m[env]
    assert f["runs"] == 3, (env, f)
    assert abs(f["phi_deg"] - phi) < 0.1, (env, "phi'", f["phi_deg"], phi)
    assert abs(1e-3 * f["c_Pa"] - c_kpa) < 0.1, (env, "c'", 1e-3 * f["c_Pa"], c_kpa)
    assert f["r_squared"] > 0.9999, (env, f)
assert [r["sigma3_Pa"] for r in m["runs"]] == [50e3, 100e3, 200e3], m["runs"]
PYEOF
# The page shows the same fit in its table, and each run's own angle (c' = 0) beside it.
grep -q "<tr><td>peak</td><td>34.00</td><td>5.00</td>" "$cmp_dir/index.html" || fail "the page's fit table lacks phi' 34.00, c' 5.00"
grep -q "<tr><td>critical state</td><td>31.00</td><td>0.00</td>" "$cmp_dir/index.html" \
  || fail "the page's fit table lacks phi'_cs 31.00, c'_cs 0.00"
phi100="$("$PY" -c 'import json,sys; print("%.2f" % json.load(open(sys.argv[1]))["triaxial"]["peak_friction_angle_deg"])' "$tmp/tx/s100/run.json")"
grep -q "$phi100" "$cmp_dir/index.html" || fail "the page lacks the 100 kPa run's own phi'_p $phi100"
[ "$(grep -o '<td>s[0-9]*</td>\|>s[0-9]*</a></td>' "$cmp_dir/index.html" | tr -dc '0-9\n' | paste -sd' ')" = "50 100 200" ] \
  || fail "the per-run table is not sorted by sigma_3"
pass "triaxial comparison: Mohr circles, phi' and c' recovered within 0.1 deg and 0.1 kPa (mohr_coulomb.json and page)"

# The same run twice: one sigma_3, so no envelope; the page says why.
"$GRAINLAB" report "$tmp/tx/s100" "$tmp/tx/s100" --out "$tmp/tx/same" >/dev/null || fail "comparison of one run twice failed"
grep -q "no peak envelope: every circle has the same centre" "$tmp/tx/same/index.html" || fail "a fit on one sigma_3 is not refused"
"$PY" -c 'import json,sys; assert json.load(open(sys.argv[1]))["peak"]["phi_deg"] is None' "$tmp/tx/same/mohr_coulomb.json" \
  || fail "mohr_coulomb.json gives a phi' from one sigma_3"
pass "one sigma_3 twice: the fit refused with a note"

set +e
msg="$("$GRAINLAB" report "$tmp/tx/s100" "$tmp/runs/angular" --out "$tmp/tx/mixed" 2>&1 >/dev/null)"; rc=$?
set -e
[ "$rc" -ne 0 ] || fail "grainlab.report compared a triaxial and a direct shear run"
[ "$(printf '%s\n' "$msg" | wc -l)" -eq 1 ] || fail "the refusal is not one line: $msg"
grep -q "s100: triaxial" <<<"$msg" && grep -q "angular: direct-shear" <<<"$msg" \
  || fail "the refusal does not say which run is which test: $msg"
[ ! -e "$tmp/tx/mixed" ] || fail "a refused comparison wrote its folder"
pass "refuses a triaxial + direct shear comparison: $msg"

# grainlab.report alone (python3 -m) on triaxial runs has no fit to draw, and says where it comes from.
report "$tmp/tx/s50" "$tmp/tx/s100" --out "$tmp/tx/nofit" >/dev/null || fail "grainlab.report alone failed"
grep -q "not available: mohr_coulomb.json missing (grainlab report fits" "$tmp/tx/nofit/index.html" \
  || fail "grainlab.report alone does not say that grainlab report writes the fit"
[ ! -e "$tmp/tx/nofit/mohr_circles.png" ] || fail "grainlab.report drew Mohr circles without the engine's fit"
pass "grainlab.report alone on triaxial runs: no fit of its own, a note instead"

# --- a lab test the report has no figures of: every series column against the progress column
cp -r "$tmp/tx/s100" "$tmp/tx/newtest"
rm -rf "$tmp/tx/newtest/report"
"$PY" - "$tmp/tx/newtest/run.json" <<'PYEOF'
import json, sys
p = sys.argv[1]
j = json.load(open(p))
j["config"]["test"] = "ring-shear"
j["ring-shear"] = j.pop("triaxial")
json.dump(j, open(p, "w"))
PYEOF
report "$tmp/tx/newtest" >/dev/null || fail "grainlab.report failed on a test it does not know"
check_report "$tmp/tx/newtest/report" series.png
grep -q "grainlab ring-shear report" "$tmp/tx/newtest/report/index.html" || fail "the unknown test's page lacks its name"
grep -q "against axial_strain" "$tmp/tx/newtest/report/index.html" || fail "the unknown test's columns are not against its progress"
grep -q "<th>peak_stress_ratio</th>" "$tmp/tx/newtest/report/index.html" || fail "the unknown test's own run.json group is not shown"
[ "$(ls "$tmp/tx/newtest/report"/*.png | wc -l)" -eq 1 ] || fail "the unknown test got figures of a known test"
pass "a test grainlab.report does not know: every series column against its progress column (series.png)"

# The four-sand study report (grainlab.report.study) on fabricated runs: a
# study.json naming four sand runs and three damping runs.
mkdir -p "$tmp/study"
for k in glass-beads:rounded:3 rounded:rounded:4 rounded-seed8:rounded:11 sub-angular:sub-angular:5 angular:angular:6 \
         damping-20-10:glass-beads:7 damping-40-20:glass-beads:8 damping-80-40:glass-beads:9; do
  IFS=: read -r name preset seed <<<"$k"
  "$PY" "$here/make_fake_run.py" "$tmp/study/$name" --preset "$preset" --seed "$seed" >/dev/null
done
cat > "$tmp/study/study.json" <<'JSON'
{"quick": true, "threads": 2, "target_relative_density": 0.9,
 "sands": [{"name": "glass-beads", "run_folder": "glass-beads", "e_min": 0.70, "e_max": 0.80, "run_wall_s": 10},
           {"name": "rounded", "run_folder": "rounded", "e_min": 0.60, "e_max": 0.75, "run_wall_s": 10},
           {"name": "rounded", "seed": 8, "run_folder": "rounded-seed8", "e_min": 0.61, "e_max": 0.76, "run_wall_s": 10},
           {"name": "sub-angular", "run_folder": "sub-angular", "e_min": 0.55, "e_max": 0.72, "run_wall_s": 10},
           {"name": "angular", "run_folder": "angular", "e_min": 0.50, "e_max": 0.70, "run_wall_s": 10}],
 "damping": [{"gamma_n": 20, "gamma_t": 10, "run_folder": "damping-20-10"},
             {"gamma_n": 40, "gamma_t": 20, "run_folder": "damping-40-20"},
             {"gamma_n": 80, "gamma_t": 40, "run_folder": "damping-80-40"}]}
JSON
out="$(report_study "$tmp/study")" || fail "grainlab.report.study failed: $out"
check_report "$tmp/study/report" stress_strain_overlay.png peaks_vs_roundness.png micro_vs_roundness.png damping.png
grep -q "e<sub>min</sub>" "$tmp/study/report/index.html" || fail "the study table lacks e_min"
grep -q "peak friction angle falls strictly with roundness" <<<"$out" || fail "no trend line for phi_p: $out"
grep -q "peak F/N: .*spread" <<<"$out" || fail "no damping spread: $out"
grep -q "peak friction angle falls strictly with roundness (means over seeds): .*rounded (R [0-9.]*) [0-9.]* \[[0-9.]* to [0-9.]*, 2 seeds\]" <<<"$out" \
  || fail "the trend does not give the rounded grains' mean and range over their two seeds: $out"
grep -q "rounded seed 8" "$tmp/study/report/index.html" || fail "the study table lacks the second seed's row"
grep -q "rounded: mean of 2 seeds" "$tmp/study/report/index.html" || fail "the study table lacks the rounded mean row"
pass "grainlab.report.study writes the study page with its figures, table and trends"

echo "all report tests passed"
