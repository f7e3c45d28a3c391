#!/usr/bin/env bash
# The layering check (tools/check_layering.py) on a copy of the tree: it passes on the copy as it
# is, and fails, naming the file and line, once a file of the raster stage includes the canvas
# stage's public header (an arrow pointing up).
# Usage: detects_violation.sh SOURCE_DIR [PYTHON]
set -euo pipefail
src=$(cd "$1" && pwd)
python=${2:-python3}
work=$(mktemp -d "${TMPDIR:-/tmp}/casteljau-layering.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "detects_violation: FAIL: $*" >&2; exit 1; }

cp -R "$src/src" "$src/include" "$work/"
"$python" "$src/tools/check_layering.py" --root "$work" > "$work/clean.log" 2>&1 ||
  { cat "$work/clean.log"; fail "the unmodified copy does not pass"; }

victim=$(cd "$work" && find src/raster -name '*.cpp' | sort | head -1)
[ -n "$victim" ] || fail "no .cpp file in src/raster"
echo '#include "casteljau/canvas.hpp"' >> "$work/$victim"
line=$(wc -l < "$work/$victim")
if "$python" "$src/tools/check_layering.py" --root "$work" > "$work/broken.log" 2>&1; then
  cat "$work/broken.log"
  fail "an include of casteljau/canvas.hpp in $victim passed"
fi
grep -q "^$victim:$line: .*casteljau/canvas.hpp" "$work/broken.log" ||
  { cat "$work/broken.log"; fail "the report does not name $victim:$line"; }
echo "detects_violation: $(grep "^$victim:$line:" "$work/broken.log")"
