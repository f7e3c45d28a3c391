#!/usr/bin/env bash
# The SDL2 clock (examples/sdl/clock_sdl.cpp) under Xvfb: a few frames at a frozen time, a
# screenshot read back from the window's renderer, compared pixel for pixel with example_clock's
# PNG of the same time (whose picture tests/figures/test_curves_golden.cpp checks). Exit 77 (a ctest skip)
# with a message when Xvfb or the SDL2 example is absent.
# Usage: check_sdl_clock.sh EXAMPLE_CLOCK EXAMPLE_SDL_CLOCK|none
set -euo pipefail
clock=$1
sdl=$2
here=$(cd "$(dirname "$0")" && pwd)
if [ "$sdl" = none ] || [ ! -x "$sdl" ]; then echo "SKIP: example_sdl_clock not built (SDL2 / libsdl2-dev absent)"; exit 77; fi
if ! command -v xvfb-run > /dev/null; then echo "SKIP: xvfb-run not found (Debian package xvfb)"; exit 77; fi
work=$(mktemp -d "${TMPDIR:-/tmp}/casteljau-sdl.XXXXXX")
trap 'rm -rf "$work"' EXIT
"$clock" 10:08:30 "$work/expected.png" 300 > /dev/null
SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software xvfb-run -a -s "-screen 0 640x480x24" \
  "$sdl" --frames 5 --time 10:08:30 --size 300 --screenshot "$work/screenshot.png"
python3 - "$work/expected.png" "$work/screenshot.png" "$here/../install" <<'PY'
import sys
sys.path.insert(0, sys.argv[3])
from png_check import decode
ew, eh, e = decode(sys.argv[1])
gw, gh, g = decode(sys.argv[2])
assert (ew, eh) == (gw, gh), ((ew, eh), (gw, gh))
diff = sum(1 for y in range(eh) for x in range(ew) if e(x, y) != g(x, y))
print("sdl_clock: %d of %d pixels differ from example_clock's PNG" % (diff, ew * eh))
sys.exit(1 if diff else 0)
PY
