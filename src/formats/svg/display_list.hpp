// Internal (formats): the SVG display list, what converting an SVG document produces and what
// drawing it consumes (draw.cpp). Converting (convert.cpp and the per-feature files beside it)
// resolves the cascade, references, units and viewports once; the list holds only geometry in
// user space, the transform to document pixels and resolved paint, so drawing needs no SVG
// knowledge and tests can check what a document converts to without comparing pixels.
//
// The list is flat: groups, clips, masks and filters are begin/end pairs of items that enclose
// the items drawn inside them, and pairs nest like brackets.
// Coordinates: `path` is in user space; `transform` maps it to document pixels (the viewBox
// mapping of the root included), before the base transform the caller draws with.
// Thread-safety: plain values; a converted list may be drawn from several threads at once.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/blend_mode.hpp"
#include "casteljau/canvas.hpp"
#include "casteljau/filter.hpp"
#include "casteljau/font.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/path.hpp"
#include "casteljau/shader.hpp"
#include "casteljau/stroke.hpp"
#include "casteljau/svg.hpp"

namespace casteljau::svg {

struct PatternTile;

struct DisplayItem {
    enum Kind {
        // Fills `path` with `color` (or `shader`, or `pattern`) under `rule`, times `opacity`.
        Fill,
        // Strokes `path` with `stroke`, painted like a Fill.
        Stroke,
        // Opens a transparent layer: a group with `opacity` < 1, a clip-path or mask, a
        // `mix-blend-mode` (`blend`) or isolation. EndLayer composites it back with its `opacity`
        // and `blend`.
        BeginLayer,
        EndLayer,
        // Clips what follows, up to PopClip, to the bounds of `path` (a viewport or image box).
        PushClip,
        PopClip,
        // The content of a clipPath, drawn into a mask layer up to EndMask; that mask's alpha
        // multiplies the enclosing layer (the one the clipped element is drawn in).
        BeginClip,
        // The content of a mask up to EndMask, which multiplies the enclosing layer by its
        // luminance (`luminance` true) or alpha.
        BeginMask,
        // Closes a BeginClip or a BeginMask.
        EndMask,
        // An <image> of an SVG document (`svg_image`), drawn with `transform` as its base.
        SvgImage,
        // Opens a layer for a filtered element; EndFilter applies `filters` to it, in the user space
        // of EndFilter's `transform`, and draws the result.
        BeginFilter,
        EndFilter,
        // A path never drawn that counts in bounding boxes (a hidden or fully transparent element).
        Bounds,
        // Colour glyph `glyph` of `font` at `glyph_size` px per em, its origin at the origin of
        // the space `transform` maps (y down), in its palette's colours; `color` stands for the
        // text colour entry and `opacity` multiplies it all.
        ColorGlyph
    } kind = Fill;
    bool luminance = false;               // BeginMask: luminance (true) or alpha mask
    BlendMode blend = BlendMode::Normal;  // BeginLayer: mix-blend-mode
    Path path;                            // user space
    Affine transform;                     // user space -> document pixel space
    Color color;
    std::shared_ptr<const Shader> shader;          // a gradient or image instead of `color`
    std::shared_ptr<const SvgDocument> svg_image;  // SvgImage: drawn with `transform` as its base
    std::shared_ptr<const PatternTile> pattern;    // a pattern instead of `color`: rendered per fill
    FillRule rule = FillRule::NonZero;
    double opacity = 1;                // fill/stroke: multiplies colour alpha; layer: group opacity
    StrokeStyle stroke;                // Stroke items
    std::shared_ptr<const Font> font;  // ColorGlyph
    std::uint32_t glyph = 0;           // ColorGlyph: glyph id
    double glyph_size = 0;             // ColorGlyph: px per em
    std::shared_ptr<const std::vector<filter::FilterGraph>>
        filters;  // EndFilter: applied in order, in the user space of `transform`
};

using DisplayList = std::vector<DisplayItem>;

// A pattern's tile: its content (items in the fill's user space), the tile rectangle in pattern
// space, and the pattern space -> user space transform (patternTransform).
struct PatternTile {
    DisplayList items;
    Rect tile;
    Affine transform;
};

// A document converted: its output size, its display list and the warnings of reading it.
struct ConvertedDocument {
    int width = 0, height = 0;       // output size: the intrinsic size rounded, at least 1
    double fwidth = 0, fheight = 0;  // intrinsic size, fractional
    Affine view;                     // viewBox -> pixels
    DisplayList items;
    std::vector<std::string> warnings;
};

// Reads an SVG document (gzip-compressed or not) and converts it. Throws Error as
// SvgDocument::parse does; `source` (a path, or empty) names the input in the message about a
// missing SvgOptions::export_id.
ConvertedDocument convert_document(std::string_view input, const SvgOptions& options, std::string_view source = {});

// The display list of a document, without drawing it.
inline DisplayList convert(std::string_view input, const SvgOptions& options = {}) {
    return convert_document(input, options).items;
}

// Draws `items` onto `canvas`, mapping document pixels by `base`.
void draw(const DisplayList& items, Canvas& canvas, const Affine& base);

}  // namespace casteljau::svg
