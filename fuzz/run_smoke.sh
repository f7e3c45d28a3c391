#!/usr/bin/env bash
# Builds (if needed) and runs one fuzz target for SECONDS on its seed corpus (fuzz/corpus/NAME,
# where NAME is TARGET without the fuzz_ prefix), in a scratch copy so that the committed corpus is
# never changed, with the dictionary fuzz/dict/NAME.dict when there is one; inputs that crash, leak
# or time out are written to BUILD/artifacts/. Exits non-zero when the fuzzer finds a crash, leak,
# timeout or sanitizer report.
# Usage: fuzz/run_smoke.sh TARGET SECONDS     e.g. fuzz/run_smoke.sh fuzz_svg 60
# The build folder is $CASTELJAU_FUZZ_BUILD, by default build-fuzz/ in the checkout; an input
# running longer than $CASTELJAU_FUZZ_TIMEOUT seconds (default 10) is a finding.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
target=${1:?usage: run_smoke.sh TARGET SECONDS}
seconds=${2:?usage: run_smoke.sh TARGET SECONDS}
build=${CASTELJAU_FUZZ_BUILD:-$root/build-fuzz}
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASTELJAU_BUILD_FUZZ=ON \
    -DCASTELJAU_BUILD_TESTS=OFF -DCASTELJAU_BUILD_BENCH=OFF -DCASTELJAU_BUILD_EXAMPLES=OFF > /dev/null
fi
cmake --build "$build" --target "$target" -j"${CASTELJAU_JOBS:-2}" > "$build/fuzz-build-$target.log" 2>&1 ||
  { tail -30 "$build/fuzz-build-$target.log"; exit 1; }
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
name=${target#fuzz_}
cp -r "$root/fuzz/corpus/$name/." "$corpus/"
case "$name" in
  map_data)
    # Each seed is tried with every reader: the first byte chooses it (see fuzz_map_data.cpp).
    for f in "$root"/tests/data/maps/*.json "$root"/tests/data/maps/*.geojson "$root"/fuzz/corpus/map_data/*; do
      for b in 0 1 2 3 8 12 19; do
        { printf "\\$(printf '%03o' "$b")"; cat "$f"; } > "$corpus/$(basename "$f").$b"
      done
    done ;;
esac
mkdir -p "$build/artifacts"
# Targets that lay out text keep no system fallback answers on disk: the user's cache is left alone.
export CASTELJAU_CACHE_DIR=
dict=()
[ -f "$root/fuzz/dict/$name.dict" ] && dict=(-dict="$root/fuzz/dict/$name.dict")
"$build/fuzz/$target" "${dict[@]}" -max_total_time="$seconds" -max_len=131072 -timeout="${CASTELJAU_FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 \
  -artifact_prefix="$build/artifacts/$target-" -print_final_stats=1 "$corpus"
