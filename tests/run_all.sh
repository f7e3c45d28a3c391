#!/usr/bin/env bash
# The whole test suite: the Release build's tests, then one clang build under AddressSanitizer +
# UndefinedBehaviorSanitizer that runs a short fuzz of every libFuzzer target and the same suite
# again. Ends with ctest's summary.
# Usage: tests/run_all.sh   (from the repository root, after the README's first command)
#
# The sanitizer build lives outside the checkout (as packagers build: `cmake -S casteljau -B
# /tmp/build`), so every run also shows that the suite does not depend on where the build folder
# is. Its folder is $CASTELJAU_SANITIZE_BUILD_DIR, by default one per checkout under $TMPDIR;
# under CI (CI=true) it is removed at the end. CASTELJAU_FUZZ_SECONDS sets each fuzz target's run
# (default 60).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=${CASTELJAU_JOBS:-2}
key=$(printf '%s' "$root" | cksum | cut -d' ' -f1)
san=${CASTELJAU_SANITIZE_BUILD_DIR:-${TMPDIR:-/tmp}/casteljau-sanitize-$key}
cleanup=()
if [ "${CI:-}" = true ]; then
  [ -n "${CASTELJAU_SANITIZE_BUILD_DIR:-}" ] || cleanup+=("$san")
  trap 'rm -rf "${cleanup[@]}"' EXIT
fi

# Each stage's heading shows the minutes spent so far (CI's time budget is 30 minutes on 2 cores).
stage() { echo "== [$((SECONDS / 60)) min] $*"; }
stage "Release build: tests"
# Configured again: the test packages (.ci/test-packages.txt) may have come after the first
# configure, and the benchmarks' peers are looked for then.
cmake -S . -B build > /dev/null
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

stage "AddressSanitizer + UndefinedBehaviorSanitizer build (clang, in $san): tests and fuzz targets"
# One build serves both: the libFuzzer targets and the test suite link the same sanitized objects
# (the library, the command line and the fuzz targets also carry libFuzzer's coverage
# instrumentation, see fuzz/CMakeLists.txt). -O1 with line tables only (-g1): what the sanitizers'
# documentation suggests; reports still name functions, files and lines.
mkdir -p "$san"
CC=clang CXX=clang++ cmake -S . -B "$san" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASTELJAU_SANITIZE=ON -DCASTELJAU_BUILD_FUZZ=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCASTELJAU_WERROR=ON -DCASTELJAU_BUILD_BENCH=OFF -DCASTELJAU_BUILD_EXAMPLES=OFF > "$san/configure.log"
cmake --build "$san" -j"$jobs" > "$san/build.log" 2>&1 || { tail -50 "$san/build.log"; exit 1; }

stage "Fuzz smoke: every libFuzzer target for ${CASTELJAU_FUZZ_SECONDS:-60} s on its seed corpus (fuzz/)"
CASTELJAU_FUZZ_BUILD=$san fuzz/run_all_smoke.sh "${CASTELJAU_FUZZ_SECONDS:-60}"

stage "AddressSanitizer + UndefinedBehaviorSanitizer: tests"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The source checks (formatting, layering) read files, not code under test: the Release run covers them.
ctest --test-dir "$san" --output-on-failure -j"$jobs" -E '^(format|layering|layering_detects_violation)$'
