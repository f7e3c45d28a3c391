#!/usr/bin/env bash
# The whole test suite: the Release build's tests, then the same suite built and run under
# AddressSanitizer + UndefinedBehaviorSanitizer, with a short run of every fuzz target in between.
# Ends with ctest's summary.
# Usage: tests/run_all.sh   (from the repository root, after the README's first command)
#
# The sanitizer build lives outside the checkout (as packagers build: `cmake -S casteljau -B
# /tmp/build`), so every run also shows that the suite does not depend on where the build folder
# is. Its folder is $CASTELJAU_SANITIZE_BUILD_DIR, by default one per checkout under $TMPDIR;
# under CI (CI=true) it is removed at the end. The fuzz build is likewise outside the checkout
# ($CASTELJAU_FUZZ_BUILD); CASTELJAU_FUZZ_SECONDS sets each target's run (default 60).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=${CASTELJAU_JOBS:-2}
key=$(printf '%s' "$root" | cksum | cut -d' ' -f1)
san=${CASTELJAU_SANITIZE_BUILD_DIR:-${TMPDIR:-/tmp}/casteljau-sanitize-$key}
fuzz_build=${CASTELJAU_FUZZ_BUILD:-${TMPDIR:-/tmp}/casteljau-fuzz-$key}
cleanup=()
if [ "${CI:-}" = true ]; then
  [ -n "${CASTELJAU_SANITIZE_BUILD_DIR:-}" ] || cleanup+=("$san")
  [ -n "${CASTELJAU_FUZZ_BUILD:-}" ] || cleanup+=("$fuzz_build")
  trap 'rm -rf "${cleanup[@]}"' EXIT
fi

echo "== Release build: tests"
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

echo "== Fuzz smoke: every libFuzzer target for ${CASTELJAU_FUZZ_SECONDS:-60} s on its seed corpus (fuzz/)"
CASTELJAU_FUZZ_BUILD=$fuzz_build fuzz/run_all_smoke.sh "${CASTELJAU_FUZZ_SECONDS:-60}"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build (in $san): tests"
mkdir -p "$san"
# -O1 with line tables only (-g1): half the compile time of -O2 -g on this code base, and what
# the sanitizers' own documentation suggests; reports still name functions, files and lines.
cmake -S . -B "$san" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASTELJAU_SANITIZE=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCASTELJAU_WERROR=ON -DCASTELJAU_BUILD_BENCH=OFF -DCASTELJAU_BUILD_EXAMPLES=OFF > "$san/configure.log"
cmake --build "$san" -j"$jobs" > "$san/build.log" 2>&1 || { tail -50 "$san/build.log"; exit 1; }
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$san" --output-on-failure -j"$jobs"
