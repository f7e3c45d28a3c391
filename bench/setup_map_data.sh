#!/bin/sh
# Installs the benchmark's map data from npm into bench/data/ (not needed by the tests):
# world-atlas 2.0.2 (Natural Earth 1:10m and 1:50m countries as TopoJSON, public domain data) and
# @geo-maps/countries-land-10km 0.6.0 (the world's countries as GeoJSON, MIT licence).
# Usage: bench/setup_map_data.sh   then   build/bench/map_bench bench/data/countries-10m.json --layer countries
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && npm install --silent --no-save world-atlas@2.0.2 @geo-maps/countries-land-10km@0.6.0 >/dev/null)
mkdir -p "$root/bench/data"
cp "$work/node_modules/world-atlas/countries-10m.json" "$work/node_modules/world-atlas/countries-50m.json" "$root/bench/data/"
cp "$work/node_modules/@geo-maps/countries-land-10km/map.geo.json" "$root/bench/data/countries-land-10km.geo.json"
echo "bench/data: $(ls "$root/bench/data")"
