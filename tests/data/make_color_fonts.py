#!/usr/bin/env python3
# Builds the small colour fonts of the colour glyph tests (tests/test_text_color.cpp) and of the
# text fuzz target, with fontTools (Debian python3-fonttools):
#   python3 tests/data/make_color_fonts.py tests/data
# writes, in that folder:
#   emoji_cbdt_test.ttf  Noto Color Emoji (Debian fonts-noto-color-emoji, SIL Open Font License,
#                        see emoji_cbdt_test.LICENSE.txt, which covers both) cut down to U+1F44B, U+1F600 and U+2764:
#                        CBDT/CBLC bitmaps (PNG, one strike of 109 ppem)
#   emoji_sbix_test.ttf  the same three bitmaps in an sbix table (empty glyf outlines)
#   colr_test.ttf        COLR v0/v1 and CPAL, described below.
#   svg_test.ttf         an SVG table (OpenType SVG glyph documents), described below.
# colr_test.ttf: units per em 1000, ascender 1000, descender 0. Outline glyphs: "square" (100..900 both ways) and
# "inner" (300..700). Colour glyphs, mapped to letters:
#   A  COLR v1: square filled with a linear gradient red -> blue from x 100 to 900, then inner with
#      a radial gradient yellow -> green, centre (500, 500), radius 0 -> 300
#   B  COLR v1: square with a horizontal linear gradient blue -> red rotated 90 degrees about
#      (500, 500) (so it runs from blue at y 100 up to red at y 900)
#   C  COLR v1: square with a sweep gradient red -> blue -> red, centre (500, 500), 0 .. 360 degrees
#   D  COLR v0: square in palette entry 1 (blue), inner in entry 0xFFFF (the text colour)
#   E  COLR v1: composite dest-out: square in blue with inner cut out
#   F  COLR v1: square in palette entry 0 (red in palette 0, green in palette 1), clip box 100..500
# Two palettes: 0 = red, blue, yellow, green; 1 = green, yellow, blue, red.
# svg_test.ttf: units per em 1000, ascender 1000, descender 0; every letter has the outline "square"
# (100..900 both ways, advance 1000) and an SVG document (user units: font units, y down):
#   A  its own document: red rectangle x 100..900, y -900..-500 over a blue one, y -500..-100
#   B  its own document, gzip-compressed: green rectangle x 200..600, y -700..-300
#   C, D  one document for both: C the red rectangle x 100..500, D the blue one x 500..900 (y -900..-100)
#   E  a malformed document (so the outline is drawn)
import os
import sys

from fontTools.colorLib.builder import buildCOLR, buildCPAL
from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib.tables import otTables as ot


def box(x0, y0, x1, y1):
    pen = TTGlyphPen(None)
    pen.moveTo((x0, y0))
    pen.lineTo((x0, y1))
    pen.lineTo((x1, y1))
    pen.lineTo((x1, y0))
    pen.closePath()
    return pen.glyph()


def empty():
    return TTGlyphPen(None).glyph()


def stops(*entries):
    return {"Extend": "pad", "ColorStop": [{"StopOffset": o, "PaletteIndex": i, "Alpha": 1.0} for o, i in entries]}


def glyph(name, paint):
    return {"Format": ot.PaintFormat.PaintGlyph, "Glyph": name, "Paint": paint}


def solid(index):
    return {"Format": ot.PaintFormat.PaintSolid, "PaletteIndex": index, "Alpha": 1.0}


def square_em_tables(fb, names, glyphs, family):
    """The outline, metrics and name tables of a test font of 1000 units per em, every glyph
    advancing 1000, ascender 1000, descender 0."""
    fb.setupGlyf(glyphs)
    glyf = fb.font["glyf"]
    # Left side bearings equal to the outlines' xMin, so that FreeType does not move them.
    fb.setupHorizontalMetrics({n: (1000, getattr(glyf[n], "xMin", 0)) for n in names})
    fb.setupHorizontalHeader(ascent=1000, descent=0)
    fb.setupOS2(sTypoAscender=1000, sTypoDescender=0, sTypoLineGap=0, usWinAscent=1000, usWinDescent=0)
    fb.setupNameTable({"familyName": family, "styleName": "Regular"})
    fb.setupPost()


def make_cbdt(out):
    from fontTools import subset
    options = subset.Options()
    options.layout_features = []
    font = subset.load_font(NOTO_EMOJI, options)
    subsetter = subset.Subsetter(options)
    subsetter.populate(unicodes=EMOJI)
    subsetter.subset(font)
    font.recalcTimestamp = False
    font["head"].created = font["head"].modified = 0
    font.save(out)


def make_sbix(cbdt_path, out):
    from fontTools.ttLib import TTFont, newTable
    from fontTools.ttLib.tables.sbixGlyph import Glyph
    from fontTools.ttLib.tables.sbixStrike import Strike
    cbdt = TTFont(cbdt_path)
    names = cbdt.getGlyphOrder()
    fb = FontBuilder(cbdt["head"].unitsPerEm, isTTF=True)
    fb.setupGlyphOrder(names)
    fb.setupCharacterMap({u: n for u, n in cbdt.getBestCmap().items()})
    fb.setupGlyf({n: empty() for n in names})
    fb.setupHorizontalMetrics({n: cbdt["hmtx"][n] for n in names})
    fb.setupHorizontalHeader(ascent=cbdt["hhea"].ascent, descent=cbdt["hhea"].descent)
    fb.setupOS2()
    fb.setupNameTable({"familyName": "Casteljau sbix Test", "styleName": "Regular"})
    fb.setupPost()
    sbix = newTable("sbix")
    sbix.version, sbix.flags = 1, 1
    strike = Strike(ppem=109, resolution=72)
    for name, bitmap in cbdt["CBDT"].strikeData[0].items():
        bitmap.decompile()
        # The bitmap's bottom-left corner sits originOffset strike pixels from the glyph origin.
        strike.glyphs[name] = Glyph(glyphName=name, graphicType="png ", originOffsetX=bitmap.metrics.BearingX,
                                    originOffsetY=bitmap.metrics.BearingY - bitmap.metrics.height,
                                    imageData=bitmap.imageData)
    sbix.strikes = {109: strike}
    fb.font["sbix"] = sbix
    fb.font.recalcTimestamp = False
    fb.font["head"].created = fb.font["head"].modified = 0
    fb.save(out)


def make_colr(out):
    names = [".notdef", "space", "square", "inner", "A", "B", "C", "D", "E", "F"]
    fb = FontBuilder(1000, isTTF=True)
    fb.setupGlyphOrder(names)
    fb.setupCharacterMap({0x20: "space", 0x41: "A", 0x42: "B", 0x43: "C", 0x44: "D", 0x45: "E", 0x46: "F"})
    glyphs = {n: empty() for n in names}
    glyphs[".notdef"] = box(100, 0, 900, 800)
    glyphs["square"] = box(100, 100, 900, 900)
    glyphs["inner"] = box(300, 300, 700, 700)
    square_em_tables(fb, names, glyphs, "Casteljau COLR Test")
    linear = {"Format": ot.PaintFormat.PaintLinearGradient, "ColorLine": stops((0, 0), (1, 1)),
              "x0": 100, "y0": 0, "x1": 900, "y1": 0, "x2": 100, "y2": 100}
    radial = {"Format": ot.PaintFormat.PaintRadialGradient, "ColorLine": stops((0, 2), (1, 3)),
              "x0": 500, "y0": 500, "r0": 0, "x1": 500, "y1": 500, "r1": 300}
    rotated = {"Format": ot.PaintFormat.PaintRotateAroundCenter, "angle": 90, "centerX": 500, "centerY": 500,
               "Paint": {"Format": ot.PaintFormat.PaintLinearGradient, "ColorLine": stops((0, 1), (1, 0)),
                         "x0": 100, "y0": 0, "x1": 900, "y1": 0, "x2": 100, "y2": 100}}
    sweep = {"Format": ot.PaintFormat.PaintSweepGradient, "ColorLine": stops((0, 0), (0.5, 1), (1, 0)),
             "centerX": 500, "centerY": 500, "startAngle": 0, "endAngle": 360}
    composite = {"Format": ot.PaintFormat.PaintComposite, "CompositeMode": "dest_out",
                 "SourcePaint": glyph("inner", solid(0)), "BackdropPaint": glyph("square", solid(1))}
    colr = buildCOLR(
        {
            "A": {"Format": ot.PaintFormat.PaintColrLayers, "Layers": [glyph("square", linear), glyph("inner", radial)]},
            "B": glyph("square", rotated),
            "C": glyph("square", sweep),
            "D": [("square", 1), ("inner", 0xFFFF)],
            "E": composite,
            "F": glyph("square", solid(0)),
        },
        glyphMap=fb.font.getReverseGlyphMap(),
        clipBoxes={"F": (100, 100, 500, 500)},
    )
    fb.font["COLR"] = colr
    red, blue, yellow, green = (1, 0, 0, 1), (0, 0, 1, 1), (1, 1, 0, 1), (0, 0.5, 0, 1)
    fb.font["CPAL"] = buildCPAL([[red, blue, yellow, green], [green, yellow, blue, red]])
    # Fixed timestamps, so that the file is the same on every run.
    fb.font.recalcTimestamp = False
    fb.font["head"].created = fb.font["head"].modified = 0
    fb.save(out)


def make_svg(out):
    from fontTools.ttLib import newTable
    from fontTools.ttLib.tables.S_V_G_ import SVGDocument
    names = [".notdef", "space", "A", "B", "C", "D", "E", "F", "G"]
    fb = FontBuilder(1000, isTTF=True)
    fb.setupGlyphOrder(names)
    fb.setupCharacterMap({0x20: "space", 0x41: "A", 0x42: "B", 0x43: "C", 0x44: "D", 0x45: "E", 0x46: "F",
                          0x47: "G"})
    glyphs = {n: box(100, 100, 900, 900) for n in names}
    glyphs["space"] = empty()
    square_em_tables(fb, names, glyphs, "Casteljau SVG Test")
    ns = 'xmlns="http://www.w3.org/2000/svg"'
    a = ('<svg %s><g id="glyph2"><rect x="100" y="-900" width="800" height="400" fill="#ff0000"/>'
         '<rect x="100" y="-500" width="800" height="400" fill="#0000ff"/></g></svg>' % ns)
    b = '<svg %s><rect id="glyph3" x="200" y="-700" width="400" height="400" fill="#00ff00"/></svg>' % ns
    cd = ('<svg %s><rect id="glyph4" x="100" y="-900" width="400" height="800" fill="#ff0000"/>'
          '<rect id="glyph5" x="500" y="-900" width="400" height="800" fill="#0000ff"/></svg>' % ns)
    e = '<svg %s><g id="glyph6"><rect x="100" y="-900" width="800" height="800"' % ns
    # F: currentColor (the text's colour) left, blue right. G: context-fill (the text's colour)
    # left, currentColor right under a colour the document sets itself (green).
    f = ('<svg %s><g id="glyph7"><rect x="100" y="-900" width="400" height="800" fill="currentColor"/>'
         '<rect x="500" y="-900" width="400" height="800" fill="#0000ff"/></g></svg>' % ns)
    g = ('<svg %s><g id="glyph8" style="color:#00ff00"><rect x="100" y="-900" width="400" height="800" '
         'fill="context-fill"/><rect x="500" y="-900" width="400" height="800" fill="currentColor"/></g></svg>' % ns)
    svg = newTable("SVG ")
    svg.docList = [SVGDocument(a, 2, 2), SVGDocument(b, 3, 3, compressed=True), SVGDocument(cd, 4, 5),
                   SVGDocument(e, 6, 6), SVGDocument(f, 7, 7), SVGDocument(g, 8, 8)]
    fb.font["SVG "] = svg
    fb.font.recalcTimestamp = False
    fb.font["head"].created = fb.font["head"].modified = 0
    fb.save(out)


NOTO_EMOJI = "/usr/share/fonts/truetype/noto/NotoColorEmoji.ttf"
EMOJI = [0x1F44B, 0x1F600, 0x2764]

if __name__ == "__main__":
    folder = sys.argv[1] if len(sys.argv) > 1 else "."
    make_colr(os.path.join(folder, "colr_test.ttf"))
    make_svg(os.path.join(folder, "svg_test.ttf"))
    make_cbdt(os.path.join(folder, "emoji_cbdt_test.ttf"))
    make_sbix(os.path.join(folder, "emoji_cbdt_test.ttf"), os.path.join(folder, "emoji_sbix_test.ttf"))
