#!/usr/bin/env bash
# The main job on shipped data: renders the demo pictures into out/ with the casteljau CLI.
# Usage: examples/demo.sh [BUILD_DIR] [OUT_DIR]   (defaults: build, out)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
build=${1:-$root/build}
out=${2:-$root/out}
cj="$build/casteljau"
mkdir -p "$out"
n=0
run() { "$cj" "$@"; n=$((n + 1)); }

# Paths and shapes.
run path "M 20 180 C 20 20 180 20 180 180 Z" --size 200x200 --fill "#1f77b4" --background white -o "$out/path-arch.png"
run path "M100 10 L161 190 L8 78 L192 78 L39 190 Z" --size 200x200 --fill crimson --background white \
  --fill-rule nonzero -o "$out/star-nonzero.png"
run path "M100 10 L161 190 L8 78 L192 78 L39 190 Z" --size 200x200 --fill crimson --background white \
  --fill-rule evenodd -o "$out/star-evenodd.png"
run path "M 60 100 a 40 40 0 1 0 80 0 a 40 40 0 1 0 -80 0 M 100 100 a 40 40 0 1 0 80 0 a 40 40 0 1 0 -80 0" \
  --size 240x200 --fill "rgba(0, 128, 0, 0.6)" --background white --fill-rule evenodd -o "$out/rings-evenodd.png"
run path @"$here/data/heart.path" --size 256x256 --transform "2 0 0 2 28 28" --fill "hsl(340, 80%, 55%)" \
  --background "#fffdf5" -o "$out/heart.png"
run path "M20 170 C 60 20 140 20 180 170" --size 200x200 --fill none --background white --stroke "#333" \
  --stroke-width 14 --line-cap round --dash "30 22" -o "$out/stroke-dashed.png"
run path "M30 160 L100 40 L170 160" --size 200x200 --fill none --background white --stroke teal --stroke-width 24 \
  --line-join round -o "$out/stroke-join.png"

# Text with the shipped fonts (fonts/).
fonts="$root/fonts"
run text "casteljau: Bézier curves → exact pixels (ﬁ, AV, To)" --font "$fonts/DejaVuSans.ttf" --size 36 \
  -o "$out/text-latin.png"
run text "Linux Libertine (CFF outlines): The quick brown fox jumps over the lazy dog; ffi, Th, 1234" \
  --font "$fonts/LinLibertine_R.otf" --size 28 --width 520 --align center --color "#3b2f2f" \
  --background "#fbf7ee" -o "$out/text-cff-paragraph.png"
run text "مرحبا بالعالم — hello" --font "$fonts/NotoSansArabic-Regular.ttf" --font "$fonts/DejaVuSans.ttf" \
  --size 40 -o "$out/text-arabic.png"
# Emoji (in colour) and Japanese from the system's fonts (Noto Color Emoji and Noto Sans CJK on
# Debian), Arabic and the rest from the shipped fonts.
run text "Hello 👋 こんにちは 日本語 ✓ مرحبا 🎨 Ελληνικά" --font "$fonts/DejaVuSans.ttf" \
  --font "$fonts/NotoSansArabic-Regular.ttf" --language ja --size 40 -o "$out/text-fallback.png"

# Curves: a Bézier with its de Casteljau construction, a B-spline with knots, its basis functions,
# a bicubic Bézier surface, and the clock (examples/clock.cpp, when it was built).
run bezier --points "0,0 48,96 120,120 216,72" --render "$out/bezier-construction.png" --construction 0.4
run bezier --points "30,0 60,10 80,30 90,60 90,90" --render "$out/bezier-quartic.png" --construction 0.5
run spline --kind bspline --degree 3 --points "0,60 40,0 90,20 120,90 170,100 200,30 240,50" \
  --render "$out/spline.png" --basis "$out/spline-basis.png"
run spline --kind bspline --degree 2 --knots "0 0 0 1 2 2 3 4 4 4" --points "0,0 1,2 2,0 3,2 4,0 5,2 6,0" \
  --basis "$out/basis-multiple-knot.png" --size 480x240
run spline --kind catmull-rom --points "0,50 40,0 90,40 130,10 170,60" --render "$out/catmull-rom.png" --size 400x240
run surface "$here/data/patch.json" --render "$out/surface.png" --projection cabinet --grid 12
run surface "$here/data/patch.json" --render "$out/surface-shaded.png" --grid 10 --shaded
if [ -x "$build/examples/example_clock" ]; then
  "$build/examples/example_clock" 10:08:30 "$out/clock.png" > /dev/null
  n=$((n + 1))
fi

# SVG drawings.
run svg "$here/data/shapes.svg" -o "$out/shapes.png"
run svg "$here/data/shapes.svg" --scale 3 -o "$out/shapes-3x.png"
# Gradients (linear, radial with a focus, reflected), a style sheet, use, a clip path, a mask and
# markers; librsvg's rsvg-convert draws the same picture.
run svg "$here/data/badge.svg" --zoom 2 -o "$out/svg-badge.png"

# Maps: the Natural Earth 110m countries (tests/data/maps), one colour per country, seamless
# borders stroked once; the hand-made sample across the antimeridian; a few Web Mercator tiles.
world="$root/tests/data/maps/countries-110m.json"
run map "$world" --layer countries --width 1600 --projection "+proj=robin" --fill-by name \
  --stroke "#4a4a4a" --stroke-width 0.6 --background white --padding 8 -o "$out/world-countries.png"
run map "$world" --layer countries --width 1024 --projection mercator --fill "#2f6f4f" --background "#dfeaf2" \
  -o "$out/world-mercator-seamless.png"
run map "$root/tests/data/maps/sample.geojson" --width 800 --bbox -180,-60,180,70 --fill-by kind \
  --stroke black --stroke-width 1 --point-radius 5 --background "#f7f7f7" -o "$out/sample-map.png"
rm -rf "$out/tiles"
"$cj" tiles "$world" --layer countries --zoom 0-2 --fill-by name --stroke "#4a4a4a" --stroke-width 0.6 \
  --background "#dfeaf2" -q -o "$out/tiles"
n=$((n + 21))

echo "casteljau demo: wrote $n images to $out"
