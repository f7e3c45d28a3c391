#!/usr/bin/env bash
# SVG text speed, side by side with rsvg-convert: renders every file of the resvg suite's text/
# area (379 files) at 300 px wide with each program, one process per file (as a user runs them),
# ROUNDS times, and prints the median wall time per file. Both use only the suite's fonts:
# casteljau through --font-dir, rsvg-convert through a fontconfig file naming the same folder.
# Usage: bench/svg_text_speed.sh [BUILD_DIR] [ROUNDS]      (default build, 3)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
rounds=${2:-3}
suite=${CASTELJAU_SHARED_DIR:-$root/../shared}/conformance/resvg-suite
[ -d "$suite/tests/text" ] || { echo "no resvg suite at $suite"; exit 77; }
command -v rsvg-convert > /dev/null || { echo "rsvg-convert is not installed"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/fonts.conf" <<CONF
<?xml version="1.0"?>
<!DOCTYPE fontconfig SYSTEM "fonts.dtd">
<fontconfig><dir>$suite/fonts</dir><cachedir>$work/cache</cachedir>
<alias><family>sans-serif</family><prefer><family>Noto Sans</family></prefer></alias>
<alias><family>serif</family><prefer><family>Noto Serif</family></prefer></alias>
</fontconfig>
CONF
files=("$suite"/tests/text/*/*.svg)
run_casteljau() {
  for f in "${files[@]}"; do
    "$build/casteljau" svg "$f" -w 300 -o "$work/c.png" -q --skip-system-fonts --font-dir "$suite/fonts" \
      --font-family "Noto Serif" --serif-family "Noto Serif" --sans-serif-family "Noto Sans" 2> /dev/null || true
  done
}
run_rsvg() {
  for f in "${files[@]}"; do
    FONTCONFIG_FILE="$work/fonts.conf" rsvg-convert -w 300 "$f" -o "$work/r.png" 2> /dev/null || true
  done
}
FONTCONFIG_FILE="$work/fonts.conf" fc-cache > /dev/null 2>&1 || true  # rsvg-convert's font cache, built once
median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
for tool in casteljau rsvg; do
  for ((r = 0; r < rounds; r++)); do
    start=$(date +%s%N)
    "run_$tool"
    end=$(date +%s%N)
    echo $(((end - start) / ${#files[@]} / 1000))
  done | median | awk -v t="$tool" -v n="${#files[@]}" '{printf "%-10s %d files, median %.1f ms per file\n", t, n, $1 / 1000}'
done
