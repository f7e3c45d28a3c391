#!/usr/bin/env bash
# SVG text speed, side by side with rsvg-convert: renders every file of the resvg suite's text/
# area (379 files) at 300 px wide with each program, one process per file (as a user runs them),
# the two programs alternating file by file (both see the same machine load), ROUNDS times, and
# prints the median over rounds of the wall time per file. Both use only the suite's fonts:
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
FONTCONFIG_FILE="$work/fonts.conf" fc-cache > /dev/null 2>&1 || true  # rsvg-convert's font cache, built once
now() { date +%s%N; }
# One round: every file with casteljau then with rsvg-convert, alternating, so that both see the
# same machine load; prints the two totals in nanoseconds.
round() {
  local tc=0 tr=0 t0 t1 t2
  for f in "${files[@]}"; do
    t0=$(now)
    "$build/casteljau" svg "$f" -w 300 -o "$work/c.png" -q --skip-system-fonts --font-dir "$suite/fonts" \
      --font-family "Noto Serif" --serif-family "Noto Serif" --sans-serif-family "Noto Sans" 2> /dev/null || true
    t1=$(now)
    FONTCONFIG_FILE="$work/fonts.conf" rsvg-convert -w 300 "$f" -o "$work/r.png" 2> /dev/null || true
    t2=$(now)
    tc=$((tc + t1 - t0))
    tr=$((tr + t2 - t1))
  done
  echo "$tc $tr"
}
median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
results=()
for ((r = 0; r < rounds; r++)); do results+=("$(round)"); done
n=${#files[@]}
printf '%s\n' "${results[@]}" | awk '{print $1}' | median | awk -v n="$n" '{printf "casteljau     %d files, median of rounds %.1f ms per file\n", n, $1 / n / 1e6}'
printf '%s\n' "${results[@]}" | awk '{print $2}' | median | awk -v n="$n" '{printf "rsvg-convert  %d files, median of rounds %.1f ms per file\n", n, $1 / n / 1e6}'
