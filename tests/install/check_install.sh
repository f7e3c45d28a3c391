#!/usr/bin/env bash
# The installed package as users meet it: `cmake --install` into a temporary prefix, then, from
# outside the source tree, the C++ scene with find_package(casteljau CONFIG), the C scene with
# pkg-config, and the Python scene with the ctypes binding installed by pip; their PNGs are
# compared with golden/install_scene.png (tests/install/png_check.py: sampled pixels against the
# scene's geometry, then pixel for pixel); a CMake project that sets no C++ standard
# (tests/install/consumer), with the shared and the static library; casteljau's three jobs (an SVG
# document, a map, a line of text) from C with pkg-config (examples/c/jobs.c) and from Python, each
# PNG byte-identical to the installed CLI's. Also: the shared library's SONAME and its exported
# symbols (only casteljau_* and the C++ API of namespace casteljau), the CLI and the fonts.
# Usage: check_install.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/casteljau-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
fail() { echo "check_install: FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
libdir=$(dirname "$(find "$prefix" -name 'libcasteljau.so.0' | head -1)")
[ -n "$libdir" ] && [ -f "$libdir/libcasteljau.a" ] || fail "libcasteljau.so.0 and libcasteljau.a not installed side by side"
[ -f "$prefix/include/casteljau/casteljau.h" ] && [ -f "$prefix/include/casteljau/canvas.hpp" ] || fail "headers"
[ -f "$libdir/pkgconfig/casteljau.pc" ] || fail "casteljau.pc"
[ -f "$libdir/cmake/casteljau/casteljauConfig.cmake" ] || fail "CMake package"
font=$prefix/share/casteljau/fonts/DejaVuSans.ttf
[ -f "$font" ] || fail "fonts not installed in share/casteljau/fonts"
"$prefix/bin/casteljau" --help > /dev/null || fail "installed CLI does not run"

# The shared library: its SONAME carries the major version, and it exports nothing but the API.
readelf -d "$libdir/libcasteljau.so.0" | grep -q 'SONAME.*libcasteljau\.so\.0' || fail "SONAME is not libcasteljau.so.0"
nm -D --defined-only "$libdir/libcasteljau.so.0" | awk '{print $3}' | c++filt > "$work/symbols.txt"
grep -q '^casteljau_canvas_fill_path$' "$work/symbols.txt" || fail "C API not exported"
grep -q '^casteljau::Canvas::fill_path' "$work/symbols.txt" || fail "C++ API not exported"
if grep -v -E '^(casteljau_|casteljau::|typeinfo for casteljau::|typeinfo name for casteljau::|vtable for casteljau::|non-virtual thunk to casteljau::)' \
     "$work/symbols.txt" > "$work/foreign.txt"; then
  head -20 "$work/foreign.txt" >&2
  fail "the shared library exports $(wc -l < "$work/foreign.txt") symbols outside the API"
fi

# C++ with find_package.
cmake -S "$src/tests/install/cxx" -B "$work/cxx" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_BUILD_RPATH="$libdir" > "$work/cxx.log" 2>&1 || { cat "$work/cxx.log"; fail "configure the C++ consumer"; }
cmake --build "$work/cxx" >> "$work/cxx.log" 2>&1 || { cat "$work/cxx.log"; fail "build the C++ consumer"; }
"$work/cxx/scene" "$work/scene_cxx.png" "$font" || fail "C++ scene"

# C++ with find_package from a project that sets no C++ standard: the imported targets carry it.
cmake -S "$src/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_BUILD_RPATH="$libdir" > "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; fail "configure the plain consumer"; }
cmake --build "$work/consumer" >> "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; fail "build the plain consumer (no CMAKE_CXX_STANDARD)"; }
"$work/consumer/consumer" "$work/consumer.png" || fail "plain consumer (shared library)"
"$work/consumer/consumer_static" "$work/consumer_static.png" || fail "plain consumer (static library)"

# C with pkg-config.
export PKG_CONFIG_PATH=$libdir/pkgconfig
cc -std=c99 -Wall -Wextra -Wpedantic -Werror "$src/examples/c/scene.c" $(pkg-config --cflags --libs casteljau) \
  -Wl,-rpath,"$libdir" -o "$work/scene_c" || fail "build the C scene with pkg-config"
"$work/scene_c" "$work/scene_c.png" "$font" > /dev/null || fail "C scene"

# The three jobs in C with pkg-config (examples/c/jobs.c): the same PNG bytes as the installed CLI's.
cc -std=c99 -Wall -Wextra -Wpedantic -Werror "$src/examples/c/jobs.c" $(pkg-config --cflags --libs casteljau) \
  -Wl,-rpath,"$libdir" -o "$work/jobs_c" || fail "build the C jobs with pkg-config"
badge=$src/examples/data/badge.svg
world=$src/tests/data/maps/countries-110m.json
mkdir -p "$work/jobs" "$work/jobs_cli"
"$work/jobs_c" "$badge" "$world" "$font" "$work/jobs" || fail "C jobs"
cli=$prefix/bin/casteljau
"$cli" svg "$badge" -w 256 -b white -o "$work/jobs_cli/badge.png" || fail "CLI svg"
"$cli" map "$world" --layer countries --width 480 --projection +proj=robin --fill-by name --stroke "#4a4a4a" \
  --stroke-width 0.6 --background white -o "$work/jobs_cli/world.png" || fail "CLI map"
"$cli" text "Hello, casteljau" --font "$font" -o "$work/jobs_cli/text.png" || fail "CLI text"
for job in badge world text; do
  cmp -s "$work/jobs/$job.png" "$work/jobs_cli/$job.png" || fail "C job $job.png differs from the CLI's"
done
echo "check_install: C jobs (SVG, map, text) equal the CLI's PNGs"

# Python: the binding installed with pip (no index: nothing is downloaded; python/ builds its own wheel).
pydir=$work/python
if python3 -m pip install --quiet --no-index --no-deps --target "$pydir" "$src/python" \
     > "$work/pip.log" 2>&1; then
  echo "check_install: python binding installed with pip"
else
  cat "$work/pip.log" >&2
  fail "pip install of python/"
fi
(cd "$work" && PYTHONPATH="$pydir" CASTELJAU_LIBRARY="$libdir/libcasteljau.so.0" \
   python3 "$src/examples/python/scene.py" "$work/scene_py.png" "$font") || fail "Python scene"
(cd "$work" && PYTHONPATH="$pydir" CASTELJAU_LIBRARY="$libdir/libcasteljau.so.0" python3 - <<'PY') || fail "Python binding checks"
import casteljau as cj
c = cj.Canvas(4, 2)
c.clear((10, 20, 30))
v = c.pixels()
assert v.nbytes == 4 * 4 * 2 and bytes(v[0:4]) == bytes((10, 20, 30, 255)), bytes(v[0:4])
v[0] = 99  # a view, not a copy
assert bytes(c.pixels()[0:1]) == bytes((99,))
try:
    cj.Path("M 1 2 L")
    raise SystemExit("bad path data did not raise")
except cj.Error as e:
    assert e.status == 2 and str(e), (e.status, str(e))
try:
    cj.Font("/nonexistent/font.ttf")
    raise SystemExit("a missing font did not raise")
except cj.Error as e:
    assert "nonexistent" in str(e)
assert cj.version() == "0.1.0"
try:
    import numpy
except ImportError:
    print("check_install: numpy absent, the array view is not checked")
else:
    a = c.array()
    assert a.shape == (2, 4, 4) and a.dtype == numpy.uint8
    a[1, 3] = (1, 2, 3, 4)  # a view of the canvas pixels, not a copy
    assert bytes(c.pixels()[c.stride + 12:c.stride + 16]) == bytes((1, 2, 3, 4))
    print("check_install: numpy array view checked")
cj.set_thread_count(3)
assert cj.thread_count() == 3
cj.set_thread_count(0)
assert cj.limits()["canvas_dimension"] == 32768 and cj.limits()["svg_image_nesting"] == 4
cj.set_limits(canvas_dimension=100, css_rules=7)
assert cj.limits()["canvas_dimension"] == 100 and cj.limits()["css_rules"] == 7
try:
    cj.Canvas(101, 1)
    raise SystemExit("a canvas past the lowered limit did not raise")
except cj.Error as e:
    assert e.status == 4 and "100" in str(e), (e.status, str(e))
try:
    cj.set_limits(canvas_dimension=40000)
    raise SystemExit("a limit above its ceiling did not raise")
except cj.Error as e:
    assert "canvas_dimension" in str(e)
assert cj.limits()["canvas_dimension"] == 100
cj.reset_limits()
cj.Canvas(101, 1)
print("check_install: python binding checks passed")
PY
# The three jobs in Python against the installed CLI's PNGs; the default font comes from the
# install's share/casteljau/fonts, found next to the library.
(cd "$work" && PYTHONPATH="$pydir" CASTELJAU_LIBRARY="$libdir/libcasteljau.so.0" python3 - "$badge" "$world" "$work/jobs_cli" <<'PY') || fail "Python jobs"
import sys
import casteljau as cj
badge, world, cli = sys.argv[1:4]
same = lambda data, name: data == open("%s/%s" % (cli, name), "rb").read()
assert same(cj.render_svg(badge, width=256, background="white").to_png(), "badge.png"), "svg"
image = cj.render_map(world, 480, layer="countries", projection="+proj=robin", fill_by="name", stroke="#4a4a4a",
                      stroke_width=0.6, background="white")
assert same(image.to_png(), "world.png"), "map"
assert same(cj.TextLayout("Hello, casteljau").render().to_png(), "text.png"), "text"
print("check_install: Python jobs (SVG, map, text) equal the CLI's PNGs")
PY

python3 "$src/tests/install/png_check.py" "$src/golden/install_scene.png" \
  "$work/scene_cxx.png" "$work/scene_c.png" "$work/scene_py.png" || fail "scene PNGs"
echo "check_install: OK"
