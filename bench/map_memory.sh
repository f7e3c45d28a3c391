#!/bin/sh
# Peak memory of `casteljau map` on a large GeoJSON file: the features of
# bench/data/countries-land-10km.geo.json (bench/setup_map_data.sh) repeated into one
# FeatureCollection of at least SIZE_MB megabytes (default 100), rendered at 2048 px wide.
# Prints the file size, the peak resident set size (GNU time's %M) and their ratio.
# Usage: bench/map_memory.sh [SIZE_MB] [casteljau binary]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
size_mb=${1:-100}
bin=${2:-$root/build/casteljau}
src=$root/bench/data/countries-land-10km.geo.json
[ -f "$src" ] || { echo "map_memory: $src is missing; run bench/setup_map_data.sh first" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$src" "$work/big.geojson" "$size_mb" <<'PY'
import json, sys
features = [json.dumps(f, separators=(",", ":")) for f in json.load(open(sys.argv[1]))["features"]]
body, target = ",\n".join(features), int(sys.argv[3]) * 1000 * 1000
with open(sys.argv[2], "w") as out:
    out.write('{"type":"FeatureCollection","features":[\n')
    written = 0
    while written < target:
        out.write((",\n" if written else "") + body)
        written += len(body)
    out.write("\n]}\n")
PY
bytes=$(stat -c %s "$work/big.geojson")
/usr/bin/time -f "%M %e" -o "$work/time" "$bin" map "$work/big.geojson" -o "$work/big.png" --width 2048 || { echo "map_memory: casteljau map failed" >&2; exit 1; }
read -r kb secs < "$work/time"
awk -v b="$bytes" -v kb="$kb" -v s="$secs" 'BEGIN {
  printf "file %.1f MB, peak RSS %.1f MB (%.2fx the file), %.2f s wall\n", b / 1e6, kb * 1024 / 1e6, kb * 1024 / b, s }'
