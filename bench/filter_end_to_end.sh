#!/usr/bin/env bash
# Filters end to end: whole `casteljau svg` processes against `rsvg-convert` (librsvg, Debian
# `librsvg2-bin`) on (1) a large blurred drawing written here (2000 x 2000 px: 40 circles with a
# Gaussian blur of deviation 12, a drop shadow made of blur, offset, transfer and merge, a colour matrix and a turbulence backdrop) and
# (2) all 398 filter files of the resvg suite rendered one after the other. Reports the median of
# RUNS whole-process CPU times (user + sys, after one warm-up), the two tools alternating.
# Usage: bench/filter_end_to_end.sh [RUNS]    (from the repository root, after the Release build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-7}
cj="$root/build/casteljau"
suite="$root/../shared/conformance/resvg-suite/tests/filters"
command -v rsvg-convert > /dev/null || { echo "rsvg-convert is not installed (Debian librsvg2-bin)"; exit 77; }
[ -d "$suite" ] || { echo "the resvg suite is not at $suite"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  echo '<svg xmlns="http://www.w3.org/2000/svg" width="2000" height="2000" viewBox="0 0 2000 2000">'
  echo '<filter id="blur"><feGaussianBlur stdDeviation="12"/></filter>'
  echo '<filter id="shadow"><feGaussianBlur in="SourceAlpha" stdDeviation="10"/><feOffset dx="15" dy="15"/>'
  echo '<feComponentTransfer><feFuncA type="linear" slope="0.6"/></feComponentTransfer>'
  echo '<feMerge><feMergeNode/><feMergeNode in="SourceGraphic"/></feMerge></filter>'
  echo '<filter id="noise" x="0" y="0" width="1" height="1"><feTurbulence baseFrequency="0.01" numOctaves="3"/>'
  echo '<feColorMatrix type="saturate" values="0.3"/></filter>'
  echo '<rect width="2000" height="2000" filter="url(#noise)"/>'
  echo '<g filter="url(#shadow)">'
  for i in $(seq 0 39); do
    x=$(( (i % 8) * 240 + 120 )); y=$(( (i / 8) * 380 + 180 ))
    printf '<circle cx="%d" cy="%d" r="100" fill="#%02x%02x%02x" filter="url(#blur)"/>\n' "$x" "$y" $(( i * 6 )) $(( 255 - i * 6 )) $(( (i * 37) % 256 ))
  done
  echo '</g></svg>'
} > "$work/big.svg"
cpu() { # prints user+sys seconds of one run of "$@"
  /usr/bin/time -f '%U %S' -o "$work/t" "$@" > /dev/null 2>&1 || true
  awk '{ printf "%.3f\n", $1 + $2 }' "$work/t"
}
median() { sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
suite_cj() { for f in "$suite"/*/*.svg; do "$cj" svg "$f" -w 300 -o "$work/s.png" -q || true; done; }
suite_rsvg() { for f in "$suite"/*/*.svg; do rsvg-convert -w 300 -o "$work/s.png" "$f" || true; done; }
export -f suite_cj suite_rsvg
export cj suite work
for case in big suite; do
  : > "$work/cj.txt"; : > "$work/rs.txt"
  for r in $(seq 0 "$runs"); do
    if [ "$case" = big ]; then
      a=$(cpu "$cj" svg "$work/big.svg" -o "$work/cj.png"); b=$(cpu rsvg-convert -o "$work/rs.png" "$work/big.svg")
    else
      a=$(cpu bash -c suite_cj); b=$(cpu bash -c suite_rsvg)
    fi
    [ "$r" -eq 0 ] && continue  # warm-up
    echo "$a" >> "$work/cj.txt"; echo "$b" >> "$work/rs.txt"
  done
  echo "$case: casteljau $(median < "$work/cj.txt") s, rsvg-convert $(median < "$work/rs.txt") s (median CPU of $runs)"
done
