"""The Python binding's three jobs against the command line: an SVG document, the Natural Earth
110m map with a choropleth, a tile pyramid and lines of text rendered through python/casteljau
give PNGs byte-identical to `casteljau svg`, `map`, `tiles` and `text` with the same options, and
render_svg's numpy view holds the PNG's pixels. Bad input raises casteljau.Error with the
library's message. Exit 77 (a ctest skip) without numpy.
Usage: test_python.py CASTELJAU_CLI SOURCE_DIR SCRATCH_DIR (PYTHONPATH holds python/,
CASTELJAU_LIBRARY the shared library)."""
import os
import sqlite3
import subprocess
import sys

try:
    import numpy as np
except ImportError:
    print("test_python: SKIP: numpy is not installed (Debian: python3-numpy)")
    sys.exit(77)

import casteljau as cj

CLI, SRC, OUT = sys.argv[1:4]
sys.path.insert(0, os.path.join(SRC, "tests", "install"))
from png_check import decode  # noqa: E402  (a PNG decoder independent of casteljau)

BADGE = os.path.join(SRC, "examples", "data", "badge.svg")
WORLD = os.path.join(SRC, "tests", "data", "maps", "countries-110m.json")
FONTS = os.path.join(SRC, "fonts")
FONT = os.path.join(FONTS, "DejaVuSans.ttf")
failures = []


def cli(*args):
    subprocess.run([CLI] + [str(a) for a in args], check=True, stdout=subprocess.DEVNULL)


def out(name):
    return os.path.join(OUT, "python-" + name)


def same_file(what, a, b):
    if open(a, "rb").read() != open(b, "rb").read():
        failures.append("%s: %s and %s differ" % (what, a, b))


def expect_error(what, call, status=None, needle=""):
    try:
        call()
    except cj.Error as e:
        if status is not None and e.status != status:
            failures.append("%s: status %d, expected %d (%s)" % (what, e.status, status, e))
        if needle not in str(e) or not str(e):
            failures.append("%s: message %r lacks %r" % (what, str(e), needle))
    else:
        failures.append("%s: no casteljau.Error" % what)


def check_svg():
    cli("svg", BADGE, "-o", out("badge-cli.png"), "-w", 256, "-b", "white")
    cj.svg_to_png(BADGE, out("badge.png"), width=256, background="white")
    same_file("svg_to_png -w 256 -b white", out("badge-cli.png"), out("badge.png"))

    cli("svg", BADGE, "-o", out("badge-zoom-cli.png"), "-z", 1.5, "--tolerance", 0.05)
    image = cj.render_svg(open(BADGE, "rb").read(), zoom=1.5, tolerance=0.05)
    if image.to_png() != open(out("badge-zoom-cli.png"), "rb").read():
        failures.append("render_svg(bytes, zoom=1.5, tolerance=0.05).to_png() differs from the CLI's")
    # The numpy view holds the PNG's pixels: premultiplied, as casteljau decodes the CLI's file.
    a = np.asarray(image)
    if a.shape != (image.height, image.width, 4) or a.dtype != np.uint8:
        failures.append("render_svg: array shape %s %s" % (a.shape, a.dtype))
    if not np.array_equal(a, cj.Image.from_png(image.to_png()).array()):
        failures.append("render_svg: the array differs from the decoded PNG")
    # An opaque background: the array equals the file's RGBA read by an independent decoder.
    opaque = cj.render_svg(BADGE, width=256, background="white")
    w, h, px = decode(out("badge-cli.png"))
    png = np.array([[px(x, y) for x in range(w)] for y in range(h)], dtype=np.uint8)
    if not np.array_equal(opaque.array(), png):
        failures.append("render_svg(width=256, background=white): the array differs from the CLI's PNG")

    doc = cj.SvgDocument(BADGE)
    if doc.intrinsic_size != (320.0, 240.0) or doc.output_size(height=120) != (160, 120):
        failures.append("SvgDocument sizes: %s %s" % (doc.intrinsic_size, doc.output_size(height=120)))
    canvas = cj.Canvas(640, 480)
    canvas.clear("white")
    canvas.scale(2)
    doc.render(canvas)
    cli("svg", BADGE, "-o", out("badge-2x-cli.png"), "-z", 2, "-b", "white")
    canvas.to_png(out("badge-2x.png"))
    same_file("SvgDocument.render under a canvas scale of 2", out("badge-2x-cli.png"), out("badge-2x.png"))
    text_svg = '<svg xmlns="http://www.w3.org/2000/svg" width="90" height="30"><text x="2" y="22" ' \
               'font-family="DejaVu Sans" font-size="20">Svg</text><blink/></svg>'
    doc = cj.SvgDocument(text_svg, font_dir=FONTS, skip_system_fonts=True)
    if np.asarray(doc.render_image()).max() == 0:
        failures.append("SVG text with font_dir drew nothing")
    # dpi and export_id, as the CLI's --dpi and --export-id draw them.
    squares = out("squares.svg")
    with open(squares, "w") as f:
        f.write("<svg xmlns='http://www.w3.org/2000/svg' width='1in' height='0.5in'>"
                "<rect id='red' width='0.5in' height='0.5in' fill='#ff0000'/>"
                "<rect id='blue' x='0.5in' width='0.5in' height='0.5in' fill='#0000ff'/></svg>")
    cli("svg", squares, "-o", out("squares-cli.png"), "--dpi", 192, "--export-id", "blue")
    cj.svg_to_png(squares, out("squares.png"), dpi=192, export_id="blue")
    same_file("svg_to_png dpi=192 export_id=blue", out("squares-cli.png"), out("squares.png"))
    a = np.asarray(cj.render_svg(squares, dpi=192, export_id="#blue"))
    if a.shape != (96, 192, 4) or a[40, 40, 3] != 0 or tuple(a[40, 140]) != (0, 0, 255, 255):
        failures.append("render_svg(dpi=192, export_id=#blue): shape %s, pixels %s %s" % (a.shape, a[40, 40], a[40, 140]))
    expect_error("export_id no element has", lambda: cj.SvgDocument(squares, export_id="nope"), 3, "nope")
    expect_error("dpi out of range", lambda: cj.SvgDocument(squares, dpi=0.5), 1, "dpi")


def check_map():
    args = ["--layer", "countries", "--width", 480, "--projection", "+proj=robin", "--fill-by", "name",
            "--stroke", "#4a4a4a", "--stroke-width", 0.6, "--background", "white"]
    cli("map", WORLD, "-o", out("world-cli.png"), *args)
    image = cj.render_map(WORLD, 480, layer="countries", projection="+proj=robin", fill_by="name",
                          stroke="#4a4a4a", stroke_width=0.6, background="white")
    image.to_png(out("world.png"))
    same_file("render_map choropleth (fill_by name)", out("world-cli.png"), out("world.png"))

    world = cj.MapData(WORLD, layer="countries")
    canvas = cj.Canvas(image.width, image.height)
    cj.render_map(world, projection="+proj=robin", fill_by="name", stroke="#4a4a4a", stroke_width=0.6,
                  background="white", canvas=canvas)
    if not np.array_equal(canvas.array(), image.array()):
        failures.append("render_map onto a canvas differs from the image")

    # A MapCache kept across renders of one MapData, in two sizes: the pixels of renders without it,
    # to rounding; another MapData through it is refused.
    cache = cj.MapCache()
    look = dict(projection="+proj=robin", fill_by="name", stroke="#4a4a4a", stroke_width=0.6, background="white")
    for width in (480, 300, 480):
        plain = cj.render_map(world, width, **look).array().astype(int)
        kept = cj.render_map(world, width, cache=cache, **look).array().astype(int)
        if np.abs(plain - kept).max() > 1:
            failures.append("render_map with a MapCache differs by more than one level at width %d" % width)
    try:
        cj.render_map(cj.MapData(WORLD, layer="countries"), 100, cache=cache)
        failures.append("a MapCache drew another MapData")
    except ValueError:
        pass

    style = out("style.json")
    with open(style, "w") as f:
        f.write('{"background": "#dfeaf2", "layers": [{"fill": "#c8c8c8", "stroke": "#ffffff", "width": 0.5},'
                ' {"filter": {"property": "name", "in": ["Brazil", "India", "Kenya"]}, "fill": "#d1495b"}]}')
    cli("map", WORLD, "-o", out("world-style-cli.png"), "--layer", "countries", "--width", 360, "--height", 180,
        "--bbox", "-180,-90,180,90", "--style", style, "--line-join", "miter", "--separate")
    cj.render_map(world, 360, 180, bbox="-180,-90,180,90", style=style, line_join="miter",
                  separate=True).to_png(out("world-style.png"))
    same_file("render_map --style --bbox --separate", out("world-style-cli.png"), out("world-style.png"))

    cli("tiles", WORLD, "-o", out("tiles-cli"), "--zoom", "0-1", "--layer", "countries", "--fill-by", "name",
        "--stroke", "#4a4a4a", "--metatile", 2, "-q")
    seen = []
    stats = cj.render_tiles(world, out("tiles"), "0-1", fill_by="name", stroke="#4a4a4a", metatile=2,
                            progress=lambda done, total: seen.append((done, total)))
    if stats["written"] != 5 or seen[-1] != (2, 2):
        failures.append("render_tiles: stats %s, progress %s" % (stats, seen))
    for z, x, y in [(0, 0, 0), (1, 0, 0), (1, 1, 1)]:
        tile = "%d/%d/%d.png" % (z, x, y)
        same_file("render_tiles " + tile, os.path.join(out("tiles-cli"), tile), os.path.join(out("tiles"), tile))

    mbtiles = out("world.mbtiles")
    if os.path.exists(mbtiles):
        os.remove(mbtiles)
    expect_error("render_tiles cancelled", lambda: cj.render_tiles(world, mbtiles, 1, progress=lambda d, t: False),
                 9, "cancel")
    if os.path.exists(mbtiles):
        failures.append("a cancelled MBTiles pyramid left its file")

    def boom(done, total):
        raise KeyError("from the progress callback")
    try:
        cj.render_tiles(world, mbtiles, 0, progress=boom)
        failures.append("an exception in the progress callback did not propagate")
    except KeyError:
        pass
    cj.render_tiles(world, mbtiles, "0-1", fill_by="name")
    with sqlite3.connect(mbtiles) as db:
        count = db.execute("select count(*) from tiles").fetchone()[0]
    if count != 5:
        failures.append("MBTiles holds %d tiles, expected 5" % count)


def check_text():
    cli("text", "Hello, casteljau", "--font", FONT, "-o", out("text-cli.png"))
    cj.TextLayout("Hello, casteljau", FONT).render().to_png(out("text.png"))
    same_file("TextLayout.render", out("text-cli.png"), out("text.png"))
    # The default font is the one the command line finds next to the build.
    if cj.TextLayout("Hello, casteljau").render().to_png() != open(out("text-cli.png"), "rb").read():
        failures.append("TextLayout with the default font differs from the CLI's")

    paragraph = "Wrapped and centred: a paragraph of several words, ligatures off."
    cli("text", paragraph, "--font", FONT, "--size", 20, "--width", 240, "--align", "center", "--feature", "liga=0",
        "--line-height", 1.2, "--color", "#23395b", "--background", "transparent", "--padding", 6,
        "-o", out("paragraph-cli.png"))
    layout = cj.TextLayout(paragraph, FONT, size=20, width=240, align="center", feature=["liga=0"], line_height=1.2)
    layout.render(color="#23395b", background="transparent", padding=6).to_png(out("paragraph.png"))
    same_file("TextLayout wrapped", out("paragraph-cli.png"), out("paragraph.png"))
    lines = layout.lines
    if len(lines) < 2 or " ".join(l.text.strip() for l in lines) != paragraph or layout.width != 240:
        failures.append("TextLayout lines: %s, width %s" % (lines, layout.width))

    rtl = "\u0645\u0631\u062d\u0628\u0627"
    arabic = os.path.join(FONTS, "NotoSansArabic-Regular.ttf")
    if os.path.exists(arabic):
        cli("text", rtl, "--font", FONT, "--font", arabic, "-o", out("rtl-cli.png"))
        cj.TextLayout(rtl, [FONT, arabic]).render().to_png(out("rtl.png"))
        same_file("TextLayout with a fallback font", out("rtl-cli.png"), out("rtl.png"))
        if not cj.TextLayout(rtl, [FONT, arabic]).lines[0].rtl:
            failures.append("an Arabic line is not right to left")
    canvas = cj.Canvas(200, 50)
    cj.TextLayout("draw", FONT, size=24).draw(canvas, 4, 4, color="navy")
    if canvas.array()[:, :, 3].max() == 0:
        failures.append("TextLayout.draw drew nothing")


def check_system_fonts():
    """system_fonts=True takes "日本" from the system's fonts as `casteljau text` does; the default
    (off) draws .notdef boxes as --no-system-fonts does."""
    cjk_font = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc"
    if not os.path.exists(cjk_font):
        print("test_python: SKIP system font fallback: no %s (Debian fonts-noto-cjk)" % cjk_font)
        return
    text = "Kanji \u65e5\u672c"
    cli("text", text, "--font", FONT, "-o", out("cjk-cli.png"))
    cli("text", text, "--font", FONT, "--no-system-fonts", "-o", out("cjk-plain-cli.png"))
    cj.TextLayout(text, FONT, system_fonts=True).render().to_png(out("cjk.png"))
    cj.TextLayout(text, FONT).render().to_png(out("cjk-plain.png"))
    same_file("TextLayout with system fonts", out("cjk-cli.png"), out("cjk.png"))
    same_file("TextLayout without system fonts", out("cjk-plain-cli.png"), out("cjk-plain.png"))
    if open(out("cjk.png"), "rb").read() == open(out("cjk-plain.png"), "rb").read():
        failures.append("TextLayout: system_fonts changes nothing for CJK text")


def check_palette():
    """palette=N draws a COLR glyph in CPAL palette N as --palette N does (tests/data/colr_test.ttf:
    "F" is red in palette 0, green in palette 1)."""
    colr = os.path.join(SRC, "tests", "data", "colr_test.ttf")
    for palette in (0, 1):
        cli("text", "F", "--font", colr, "--size", 40, "--palette", palette, "-o", out("palette%d-cli.png" % palette))
        layout = cj.TextLayout("F", colr, size=40, palette=palette)
        layout.render().to_png(out("palette%d.png" % palette))
        same_file("TextLayout palette %d" % palette, out("palette%d-cli.png" % palette), out("palette%d.png" % palette))
    if open(out("palette0.png"), "rb").read() == open(out("palette1.png"), "rb").read():
        failures.append("TextLayout: palette 1 draws as palette 0")


def check_errors():
    expect_error("malformed SVG", lambda: cj.render_svg(b"<svg xmlns='http://www.w3.org/2000/svg'"), 2)
    expect_error("SVG of zero width", lambda: cj.render_svg("<svg xmlns='http://www.w3.org/2000/svg' width='0'/>"), 3,
                 "positive")
    expect_error("missing SVG file", lambda: cj.svg_to_png(out("no-such.svg"), out("x.png")), 5, "no-such.svg")
    expect_error("missing font folder", lambda: cj.SvgDocument(BADGE, font_dir=out("no-fonts")), 5, "no-fonts")
    expect_error("zoom with a width", lambda: cj.render_svg(BADGE, width=10, zoom=2), 1, "zoom")
    expect_error("GeoJSON with a NaN", lambda: cj.render_map(b'{"type": "Point", "coordinates": [NaN, 1]}', 10))
    expect_error("latitude out of range", lambda: cj.render_map('{"type": "Point", "coordinates": [0, 91]}', 10), 3)
    expect_error("unknown projection", lambda: cj.render_map(WORLD, 10, projection="+proj=nonsense"), 1, "nonsense")
    expect_error("missing font", lambda: cj.TextLayout("x", out("no-such-font.ttf")), 5, "no-such-font.ttf")
    expect_error("unknown variation axis", lambda: cj.TextLayout("x", FONT, variation="wght=700"), 6, "wght")
    expect_error("negative palette", lambda: cj.TextLayout("x", FONT, palette=-1), 1, "palette")
    expect_error("bad path data", lambda: cj.Path.from_svg("M 1 2 L"), 2)
    expect_error("bad colour", lambda: cj.render_map(WORLD, 10, fill="notacolour"), 2, "notacolour")


check_svg()
check_map()
check_text()
check_system_fonts()
check_palette()
check_errors()
for f in failures:
    print("test_python: FAIL: " + f)
print("test_python: %d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
