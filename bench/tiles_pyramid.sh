#!/bin/sh
# bench/tiles_pyramid.sh: the tile pyramid's throughput: one process with 1 thread, one
# with 2 threads, and 2 shards as two 1-thread processes side by side; each into a fresh folder.
# Prints wall time, CPU time and tiles per second of wall time, then checks that the two shards
# together wrote exactly the files of the unsharded run, byte for byte.
#
# Usage: bench/tiles_pyramid.sh [INPUT] [ZOOM] [OUT]
#   INPUT defaults to the shipped 110m world (tests/data/maps/countries-110m.json), ZOOM to 0-8,
#   OUT (scratch folder, removed first) to /tmp/casteljau-pyramid.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
bin="$here/build/casteljau"
input=${1:-$here/tests/data/maps/countries-110m.json}
zoom=${2:-0-8}
out=${3:-/tmp/casteljau-pyramid}
style="--layer countries --fill-by name --stroke #333 --stroke-width 0.5 --background #cde --quiet"
rm -rf "$out"
mkdir -p "$out"

# run LABEL COMMAND...: times a command (wall and CPU of the shell's children), prints one row.
run() {
    label=$1
    shift
    t0=$(date +%s.%N)
    c0=$(awk '{print $14 + $15 + $16 + $17}' /proc/$$/stat)
    "$@"
    t1=$(date +%s.%N)
    c1=$(awk '{print $14 + $15 + $16 + $17}' /proc/$$/stat)
    tiles=$(find "$out/$label" -name '*.png' | wc -l)
    awk -v l="$label" -v w0="$t0" -v w1="$t1" -v c0="$c0" -v c1="$c1" -v n="$tiles" -v hz="$(getconf CLK_TCK)" 'BEGIN {
        wall = w1 - w0; cpu = (c1 - c0) / hz
        printf "| %s | %d | %.1f s | %.1f s | %.0f | %.0f |\n", l, n, wall, cpu, n / wall, n / cpu }'
}

echo "input $input, zoom $zoom, $(nproc) cores"
echo "| run | tiles | wall | CPU | tiles/s (wall) | tiles per CPU-second |"
echo "|---|---:|---:|---:|---:|---:|"
# shellcheck disable=SC2086
run one-thread "$bin" tiles "$input" --zoom "$zoom" $style --threads 1 -o "$out/one-thread"
# shellcheck disable=SC2086
run two-threads "$bin" tiles "$input" --zoom "$zoom" $style --threads 2 -o "$out/two-threads"
two_shards() {
    # shellcheck disable=SC2086
    "$bin" tiles "$input" --zoom "$zoom" $style --threads 1 --shard 0/2 -o "$out/two-shards" &
    p0=$!
    # shellcheck disable=SC2086
    "$bin" tiles "$input" --zoom "$zoom" $style --threads 1 --shard 1/2 -o "$out/two-shards" &
    p1=$!
    wait $p0
    wait $p1
}
run two-shards two_shards
if diff -r -q "$out/one-thread" "$out/two-shards" >/dev/null && diff -r -q "$out/one-thread" "$out/two-threads" >/dev/null; then
    echo "outputs identical: 1 thread, 2 threads and the 2 shards together (diff -r)"
else
    echo "outputs DIFFER" >&2
    exit 1
fi
