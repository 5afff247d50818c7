#!/bin/bash
# Runs each libFuzzer harness of tests/fuzz for a set time (`make fuzz`).
# Usage: scripts/run_fuzzers.sh BUILD_DIR [SECONDS_EACH [MAX_RUNS [HARNESS...]]]
#   BUILD_DIR     a build configured with -DGRAINLAB_FUZZ=ON (clang), harnesses built
#   SECONDS_EACH  wall-clock seconds per harness (default 600)
#   MAX_RUNS      executions per harness at most (default 1000000): a harness
#                 stops at whichever of the two limits comes first
#   HARNESS...    names (config, stl, ...); default every tests/fuzz/fuzz_*.cpp
# Each harness starts from its corpus in tests/fuzz/corpus/NAME and adds the
# inputs that reach new code to BUILD_DIR/fuzz-corpus/NAME (the repository's
# corpus holds seeds and regression inputs only). A finding (crash, sanitizer
# report, escaped exception, a hang over 10 s, an allocation over 1 GiB, a
# leak; those inside assimp are suppressed: tests/fuzz/lsan_suppressions.txt)
# is written to BUILD_DIR/fuzz-findings/NAME-*: reproduce it with
# `BUILD_DIR/fuzz_NAME FILE`, fix it, and add the file to the corpus. Prints a
# line per harness (executions, wall seconds, executions per second, coverage
# (libFuzzer's cov: and ft: counts), corpus size, findings); exit 1 when
# any harness found something. Runs at nice 19 (a shared machine; FUZZ_NICE
# sets another niceness).
set -u
build=${1:?usage: scripts/run_fuzzers.sh BUILD_DIR [SECONDS_EACH [MAX_RUNS [HARNESS...]]]}
seconds=${2:-600}
runs=${3:-1000000}
shift $(($# < 3 ? $# : 3))
root=$(cd "$(dirname "$0")/.." && pwd)
if [ $# -gt 0 ]; then
  names="$*"
else
  names=$(ls "$root"/tests/fuzz/fuzz_*.cpp | sed 's#.*/fuzz_##; s#\.cpp$##')
fi
mkdir -p "$build/fuzz-corpus" "$build/fuzz-findings"
found=0
for name in $names; do
  bin=$build/fuzz_$name
  [ -x "$bin" ] || { echo "$name: no harness at $bin (build the target fuzz_harnesses with GRAINLAB_FUZZ=ON)"; found=1; continue; }
  mkdir -p "$build/fuzz-corpus/$name"
  log=$build/fuzz-findings/$name.log
  before=$(ls "$build/fuzz-findings" | grep -c "^$name-")
  start=$(date +%s)
  LSAN_OPTIONS=suppressions=$root/tests/fuzz/lsan_suppressions.txt nice -n "${FUZZ_NICE:-19}" "$bin" "$build/fuzz-corpus/$name" "$root/tests/fuzz/corpus/$name" \
    -max_total_time="$seconds" -runs="$runs" -timeout=10 -malloc_limit_mb=1024 -rss_limit_mb=2048 \
    -detect_leaks=1 -print_final_stats=1 -artifact_prefix="$build/fuzz-findings/$name-" > "$log" 2>&1
  rc=$?
  after=$(ls "$build/fuzz-findings" | grep -c "^$name-")
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  secs=$(($(date +%s) - start))
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  status=$(grep -E '^#[0-9]+' "$log" | tail -1)
  cov=$(echo "$status" | grep -o 'cov: [0-9]*' | grep -o '[0-9]*')
  ft=$(echo "$status" | grep -o 'ft: [0-9]*' | grep -o '[0-9]*')
  corpus=$(ls "$build/fuzz-corpus/$name" | wc -l)
  echo "$name: ${execs:-?} executions in $secs s (${rate:-?}/s), cov ${cov:-?} ft ${ft:-?}, $corpus new corpus inputs," \
    "$((after - before)) findings (exit $rc; log $log)"
  [ $rc -eq 0 ] && [ $after -eq $before ] || found=1
done
exit $found
