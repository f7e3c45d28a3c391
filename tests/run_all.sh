#!/usr/bin/env bash
# The whole test suite: the Release build's tests, then the same suite built and run under
# AddressSanitizer + UndefinedBehaviorSanitizer. Ends with ctest's summary.
# Usage: tests/run_all.sh   (from the repository root, after the README's first command)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=${CASTELJAU_JOBS:-2}

echo "== Release build: tests"
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build: tests"
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASTELJAU_SANITIZE=ON \
  -DCASTELJAU_WERROR=ON -DCASTELJAU_BUILD_BENCH=OFF -DCASTELJAU_BUILD_EXAMPLES=OFF > build-sanitize.log
cmake --build build-sanitize -j"$jobs" >> build-sanitize.log || { tail -50 build-sanitize.log; exit 1; }
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-sanitize --output-on-failure -j"$jobs"
