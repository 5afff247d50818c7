#!/bin/bash
# kill -9 bench: a small run of each lab test is killed with SIGKILL (which
# cannot be caught: nothing is saved at the kill) at KILLS moments spread over
# the whole run, and each killed run is continued: with `--resume` when a
# checkpoint was written before the kill, else by starting it again. Every
# continued run must give a series.csv byte-identical to the same run done
# straight through, exit 0 and leave no temporary file.
#
# The moments: the straight run's processor time T (user + system) is
# measured first, and kill k (k = 0..KILLS-1) comes when the killed run has
# used T (k + u) / KILLS of processor time, u uniform in [0, 1) (seeded, so a
# rerun makes the same choice): processor time, not wall time, so that the
# kills land at the same points of the run however loaded the machine is,
# spread over deposition, compaction, consolidation and loading in
# proportion to their cost. Checkpoints are written every 0.02 s (output.checkpoint_interval), so
# most kills fall between two checkpoints of the same phase. The phase a kill
# hit is the last `phase ... from step` line the killed run printed (stdout
# line-buffered through stdbuf).
#
# Usage: bench/kill9_resume.sh [--grainlab BUILD/grainlab] [--kills N] [--tests "direct-shear oedometer triaxial"]
#                             [--work DIR] [--seed S]
# Prints one line per kill and a summary per test; exit 0 when every resume
# was byte-identical. Run it at low priority on a shared machine:
#   nice -n 19 bench/kill9_resume.sh
# A run takes about 4 s of processor time (52 rounded grains for the direct shear,
# glass beads for the oedometer and triaxial), so 20 kills of each of the
# three tests take some 5 minutes on a quiet machine.
set -u
grainlab=build/grainlab
kills=20
tests="direct-shear oedometer triaxial"
work=${TMPDIR:-/tmp}/grainlab-kill9-$$
seed=1
while [ $# -gt 0 ]; do
  case "$1" in
    --grainlab) grainlab=$2; shift 2 ;;
    --kills) kills=$2; shift 2 ;;
    --tests) tests=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "kill9_resume.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
grainlab=$(readlink -f "$grainlab")
[ -x "$grainlab" ] || { echo "kill9_resume.sh: no grainlab binary at '$grainlab'; build it or give --grainlab" >&2; exit 2; }
mkdir -p "$work"
export GRAINLAB_PYTHON=/nonexistent/python3  # no report: only the run's files matter

# The config of test $1 writing to folder $2 (the small box of tests/apps/resume_test.cpp).
config() {
  local block=""
  case "$1" in
    oedometer) block=$'test = "oedometer"\n[oedometer]\nstresses = [150e3, 200e3, 300e3]\n[material]\npreset = "glass-beads"' ;;
    triaxial) block=$'test = "triaxial"\n[triaxial]\nfinal_strain = 0.02\n[material]\npreset = "glass-beads"' ;;
  esac
  cat <<TOML
seed = 3
$block
[grains]
shapes = 4
faces = 120
[box]
length = 0.003
width = 0.003
height = 0.002
[specimen]
indices = "lab"
deposition_friction = 0.05
tolerance = 1.0
[shear]
final_strain = 0.01
[numerics]
threads = 1
[output]
snapshot_interval = 0.004
checkpoint_interval = 0.02
folder = "$2"
TOML
}

# Processor time (s) process $1 has used so far, from /proc (fields 14, 15 in clock ticks).
cpu_seconds() {
  awk -v hz="$(getconf CLK_TCK)" '{ sub(/^.*\) /, ""); printf "%.3f", ($12 + $13) / hz }' "/proc/$1/stat" 2>/dev/null
}
failures=0
for t in $tests; do
  dir=$work/$t
  rm -rf "$dir"; mkdir -p "$dir"
  config "$t" "$dir/straight" > "$dir/straight.toml"
  if ! /usr/bin/time -f "%U %S" -o "$dir/straight.time" "$grainlab" run "$dir/straight.toml" --quiet --no-report \
       > "$dir/straight.log" 2>&1; then
    echo "$t: the straight run failed:"; cat "$dir/straight.log"; exit 1
  fi
  T=$(awk '{ printf "%.3f", $1 + $2 }' "$dir/straight.time")
  echo "$t: straight run ${T} s of processor time, $(($(wc -l < "$dir/straight/series.csv") - 1)) rows"
  same=0; resumed=0; restarted=0; phases=""
  RANDOM=$seed
  for k in $(seq 0 $((kills - 1))); do
    at=$(awk -v T="$T" -v k="$k" -v n="$kills" -v u="$RANDOM" 'BEGIN { printf "%.3f", T * (k + u / 32768) / n }')
    run=$dir/kill$k
    config "$t" "$run" > "$run.toml"
    stdbuf -oL "$grainlab" run "$run.toml" --no-report > "$run.log" 2>&1 &
    pid=$!
    while used=$(cpu_seconds $pid) && [ -n "$used" ] && awk -v u="$used" -v a="$at" 'BEGIN { exit !(u < a) }'; do
      sleep 0.01
    done
    kill -9 $pid 2>/dev/null
    wait $pid 2>/dev/null; killed_rc=$?
    phase=$(grep -o 'phase [a-z-]* from step' "$run.log" | tail -1 | awk '{ print $2 }')
    [ -n "$phase" ] || phase=first
    [ $killed_rc -eq 137 ] || phase="$phase(ended:$killed_rc)"
    if [ -f "$run/checkpoint.bin" ]; then
      how=resume; resumed=$((resumed + 1))
      "$grainlab" run "$run.toml" --resume --quiet --no-report > "$run.resume.log" 2>&1; rc=$?
    else
      how=restart; restarted=$((restarted + 1))
      "$grainlab" run "$run.toml" --quiet --no-report > "$run.resume.log" 2>&1; rc=$?
    fi
    temporaries=$(find "$run" -name '.*.tmp.*' | wc -l)
    if [ $rc -eq 0 ] && [ "$temporaries" -eq 0 ] && cmp -s "$run/series.csv" "$dir/straight/series.csv"; then
      verdict=identical; same=$((same + 1))
    else
      verdict="DIFFERENT (exit $rc, $temporaries temporaries; see $run.resume.log)"; failures=$((failures + 1))
    fi
    phases="$phases $phase"
    echo "  kill $k at ${at} s of processor time in phase $phase: $how, series.csv $verdict"
    [ "$verdict" = identical ] && rm -rf "$run" "$run.toml" "$run.log" "$run.resume.log"
  done
  echo "$t: $same/$kills byte-identical ($resumed resumed from a checkpoint, $restarted started again);" \
       "kills per phase:$(echo $phases | tr ' ' '\n' | sort | uniq -c | awk '{ printf " %s %s", $2, $1 }')"
done
[ $failures -eq 0 ] && rm -rf "$work"
exit $((failures > 0))
