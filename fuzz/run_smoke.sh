#!/bin/sh
# Builds one libFuzzer target with clang in build-fuzz/ and runs it for SECONDS on a copy of its seed
# corpus (fuzz/corpus/TARGET-without-fuzz_ plus the matching test data), so the repository is
# never written to (crash/timeout inputs go to build-fuzz/). Exit status: libFuzzer's (non-zero when it found a crash, leak or timeout).
# Usage: fuzz/run_smoke.sh fuzz_map_data 60
set -eu
target=${1:?usage: fuzz/run_smoke.sh TARGET SECONDS}
seconds=${2:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-fuzz"
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASTELJAU_BUILD_FUZZ=ON \
    -DCASTELJAU_BUILD_TESTS=OFF -DCASTELJAU_BUILD_BENCH=OFF -DCASTELJAU_BUILD_EXAMPLES=OFF >/dev/null
fi
cmake --build "$build" --target "$target" -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=${target#fuzz_}
cp -r "$root/fuzz/corpus/$name" "$work/corpus"
case "$name" in
  map_data)
    # Each seed is tried with every reader: the first byte chooses it (see fuzz_map_data.cpp).
    for f in "$root"/tests/data/maps/*.json "$root"/tests/data/maps/*.geojson "$root"/fuzz/corpus/map_data/*; do
      for b in 0 1 2 3 8 12 19; do
        { printf "\\$(printf '%03o' "$b")"; cat "$f"; } > "$work/corpus/$(basename "$f").$b"
      done
    done ;;
esac
"$build/fuzz/$target" -max_total_time="$seconds" -max_len=131072 -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix="$build/" \
  -print_final_stats=1 "$work/corpus"
