// Internal (text module): colour glyphs. Which glyphs of a font are coloured (OpenType SVG
// documents, COLR v1 paint graphs, COLR v0 layers, CBDT/CBLC or sbix bitmaps), their bounds, and
// drawing one on a Canvas.
//
// SVG documents: drawn by the drawer of casteljau/text.hpp (set_svg_glyph_drawer) into a pixmap
// the size of the glyph's device bounds, like COLR glyphs; the bounds are the outline's and the
// line box's (ascender to descender over the advance) together, grown by a tenth of the em on
// every side, since the document itself is not measured. They come first when a font has several
// kinds, as in FreeType's FT_LOAD_COLOR.
//
// Bitmaps: the strike nearest above the device size (else the largest) is scaled to the device size
// by area averaging (each device pixel takes the mean of the strike's pixels under it, weighted by
// overlap: a box filter) and composited at the glyph's pixel position; under a transform that
// rotates, skews or scales unevenly the strike is drawn as an image (bilinear).
// COLR: the v1 paint graph (read by src/text/colr_table.cpp, as Debian 12's FreeType has its COLR v1
// API disabled) or the v0 layers (FreeType) are drawn through the Canvas (glyph outlines filled with exact coverage, gradients as shaders, transforms,
// clip boxes, composite modes as layers with blend modes) into a pixmap the size of the glyph's
// device bounds, which is then composited.
// Palette entry 0xFFFF is the text colour (the Paint's colour); the Paint's opacity multiplies all.
#pragma once

#include <cstdint>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/font.hpp"

namespace casteljau::text_detail {

enum class ColorGlyphKind { None, Svg, Layers, PaintGraph, Bitmap };

// Whether `font` has any colour table this module draws (an SVG table counts while an SVG glyph
// drawer is set): without one, no glyph of it is a colour glyph.
bool may_have_color_glyphs(const Font& font);

// What kind of glyph `glyph` is; None for an ordinary outline glyph (and every glyph of a font with
// no colour tables, cheaply).
ColorGlyphKind color_glyph_kind(const Font& font, std::uint32_t glyph);

// Bounds of a colour glyph in font units, y up (bitmaps: the strike's box scaled to the em).
Rect color_glyph_bounds(const Font& font, std::uint32_t glyph);

// The colours of CPAL palette `palette` (palette 0 when out of range; empty without CPAL).
std::vector<Color> font_palette(const Font& font, int palette);

// Draws colour glyph `glyph` with its origin at `origin` (layout space of `to_device`, which maps
// layout space to the canvas's pixels) at `size` px per em. Returns false when it drew nothing
// because the glyph's SVG document could not be drawn (the caller fills the outline instead).
bool draw_color_glyph(Canvas& canvas, const Font& font, std::uint32_t glyph, double size, const Affine& to_device,
                      Point origin, const Paint& paint, int palette);

// COLR drawing (src/text/colr_paint.cpp): the glyph's paint graph (or v0 layers) on `canvas`, whose
// transform maps font units (y up) to its pixels. `palette`: the CPAL colours; `foreground`: colour
// of entry 0xFFFF. Returns false when the glyph has no COLR data.
bool paint_colr_glyph(Canvas& canvas, const Font& font, std::uint32_t glyph, const std::vector<Color>& palette,
                      Color foreground);
// Whether `glyph` has a COLR v1 paint graph.
bool has_colr_paint_graph(const Font& font, std::uint32_t glyph);
// Bounds in font units of what paint_colr_glyph draws: its clip box, else the union of its
// outlines under their transforms (the em square for paints not bounded by an outline).
Rect colr_glyph_bounds(const Font& font, std::uint32_t glyph);

}  // namespace casteljau::text_detail
