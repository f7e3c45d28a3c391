#!/usr/bin/env bash
# Builds (if needed) and runs one fuzz target for SECONDS on its seed corpus (fuzz/corpus/NAME,
# where NAME is TARGET without the fuzz_ prefix), in a scratch copy so that the committed corpus is
# not changed. Exits non-zero when the fuzzer finds a crash, leak or sanitizer report.
# Usage: fuzz/run_smoke.sh TARGET SECONDS     e.g. fuzz/run_smoke.sh fuzz_svg 60
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
target=${1:?usage: run_smoke.sh TARGET SECONDS}
seconds=${2:?usage: run_smoke.sh TARGET SECONDS}
build=${CASTELJAU_FUZZ_BUILD:-$root/build-fuzz}
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASTELJAU_BUILD_FUZZ=ON \
    -DCASTELJAU_BUILD_TESTS=OFF -DCASTELJAU_BUILD_BENCH=OFF -DCASTELJAU_BUILD_EXAMPLES=OFF > /dev/null
fi
cmake --build "$build" --target "$target" -j"${CASTELJAU_JOBS:-2}" > "$build/fuzz-build.log" || { tail -30 "$build/fuzz-build.log"; exit 1; }
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp -r "$root/fuzz/corpus/${target#fuzz_}/." "$corpus/"
"$build/fuzz/$target" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 "$corpus"
