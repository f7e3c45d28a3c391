#!/usr/bin/env bash
# Runs every fuzz target of fuzz/CMakeLists.txt for SECONDS each (default 60), three at a time
# ($CASTELJAU_FUZZ_PARALLEL), each starting as soon as one before it ends, after
# building them all once. Prints one line per target (executions, result) and exits non-zero when any
# target found something; the full libFuzzer output of each is in BUILD/fuzz-TARGET.log.
# Usage: fuzz/run_all_smoke.sh [SECONDS]
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${CASTELJAU_FUZZ_BUILD:-$root/build-fuzz}
export CASTELJAU_FUZZ_BUILD=$build
targets=$(sed -n 's/^foreach(target \(.*\))$/\1/p' "$root/fuzz/CMakeLists.txt")
[ -n "$targets" ] || { echo "run_all_smoke: no targets found in fuzz/CMakeLists.txt" >&2; exit 1; }
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASTELJAU_BUILD_FUZZ=ON \
    -DCASTELJAU_BUILD_TESTS=OFF -DCASTELJAU_BUILD_BENCH=OFF -DCASTELJAU_BUILD_EXAMPLES=OFF > /dev/null || exit 1
fi
# shellcheck disable=SC2086
cmake --build "$build" --target $targets -j"${CASTELJAU_JOBS:-2}" > "$build/fuzz-build.log" 2>&1 ||
  { tail -30 "$build/fuzz-build.log"; exit 1; }
run() {
  if "$root/fuzz/run_smoke.sh" "$1" "$seconds" > "$build/fuzz-$1.log" 2>&1; then
    echo "fuzz $1: $(grep -m1 'stat::number_of_executed_units' "$build/fuzz-$1.log" | awk '{print $2}') executions in ${seconds} s, no finding"
  else
    echo "fuzz $1: FAILED (see $build/fuzz-$1.log):"
    grep -m5 -E 'ERROR|SUMMARY|Test unit written' "$build/fuzz-$1.log"
    return 1
  fi
}
fail=0
# Every target runs its SECONDS of wall time whatever the others do, so on two cores three at a time
# cost each a third of its executions and save a third of the wall time.
parallel=${CASTELJAU_FUZZ_PARALLEL:-3}
pids=()
for target in $targets; do
  run "$target" & pids+=($!)
  if [ "${#pids[@]}" -ge "$parallel" ]; then
    wait "${pids[0]}" || fail=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || fail=1; done
exit "$fail"
