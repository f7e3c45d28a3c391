// casteljau/svg.hpp: an SVG reader that draws onto a Canvas.
//
// Supported: the root size (px, physical units at SvgOptions::dpi, percentages), viewBox and every
// preserveAspectRatio form; a root with a prefix bound to the SVG namespace (<svg:svg>); .svgz;
// shapes (path, rect, circle, ellipse, line, polyline, polygon); fill and stroke with their
// properties (rules, opacity, width, caps, joins, miter limit, dashes), paint-order, visibility,
// display; transform lists and transform-origin; g, a, defs, switch (systemLanguage is matched
// against English, requiredExtensions never passes), use (of elements, symbol and svg, with x, y,
// width, height), symbol (viewBox, refX/refY), nested svg viewports clipped by overflow; paint
// servers linearGradient and radialGradient (units, gradientTransform, spreadMethod, href
// inheritance, stops) and pattern (a tile drawn at device resolution, repeated) drawn through the
// paint stage's Shader; context-fill/context-stroke in use and markers (paint servers resolved for
// the context element's box and user space); <style> sheets (src/formats/svg/css.hpp)
// with the cascade presentation attribute < sheet < style attribute and !important; clipPath and
// mask (units, clip-rule, mask-type, nested), as exact-area coverage masks of layers; markers
// (on every shape, SVG 2); the root svg's own opacity, display, clip-path, mask and filter;
// group opacity, mix-blend-mode and isolation; <image> (PNG, JPEG, GIF, WebP, SVG; see SvgOptions).
// Filters: the filter property (url() lists and the CSS filter functions) with every filter
// primitive, evaluated by the filter stage (casteljau/filter.hpp) in device pixels after the
// element is drawn into a layer, before its clip, mask and opacity
// (src/formats/svg/filter_graphs.cpp).
// Text: text, tspan, tref, textPath and a inside text (src/formats/svg/text_layout.hpp: fonts
// through FontDatabase, shaping through casteljau's HarfBuzz engine, glyphs become ordinary
// filled and stroked paths).
// Cycles (use, gradient href, clip-path, mask, marker) are broken: the repeated reference is
// skipped or the element is not drawn.
// SVG coordinates: user units, y down, mapped to pixels by the viewBox transform. Lengths: em and
// ex are of the element's computed font-size (12 where none is set, ex = em / 2); in, cm, mm, pt
// and pc are SvgOptions::dpi pixels per inch (96, CSS's, by default); percentages of
// stroke-width and dashes are of the nearest viewport's diagonal sqrt((w^2 + h^2) / 2).
// Limits (casteljau/limits.hpp, read once per document): Limits::nesting_depth, svg_elements
// (elements drawn or expanded, every copy a <use> makes counted: past it, a "use bomb", the
// document is refused with Error(Limit)), svg_image_nesting (SVG images inside SVG images; deeper
// ones are skipped with a warning), svgz_bytes (inflated .svgz), css_rules (the rest ignored with
// a warning), svg_text_chars (characters laid out per document after white-space processing, use
// copies counted; the rest dropped with a warning), the filter limits; canvas size as for Pixmap.
// Thread-safety: SvgDocument is an immutable value after parsing; render from any thread.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/font_database.hpp"
#include "casteljau/paint.hpp"

namespace casteljau {

// Where <image> may read files from. Nothing is ever fetched over the network (http:, https:,
// any URL scheme but data: is refused), absolute paths are refused, and a relative href resolves
// against `base_dir` and must stay inside `resource_root` (default: base_dir itself) after
// symbolic links are resolved. An empty base_dir (text parsed from memory) refuses every file;
// data: URIs always work.
//
// Text is drawn with fonts from `font_dirs` and `font_files` plus the system's (fontconfig) unless
// `system_fonts` is false; or, when `font_database` is set, from that database alone (share one
// between documents so that each font file is read once). The generic CSS families map to the
// `*_family` names, and `font_family` ends every font-family list (the defaults are resvg's).
// A character no face of the element's font-family list has comes from the database's other
// faces: with `system_fallback` false (the default), from any of them, the best match of weight,
// style and stretch; with it true, from the faces of the folders and files given (or of a given
// database's non-system faces) first, then from the system's fonts the way `casteljau text` finds
// them (per character cluster, in fontconfig's order for the first face's family, weight and
// slant; TextStyle::system_fonts), whether or not `system_fonts` is set. The `svg` command turns
// it on unless --no-system-fonts (or --skip-system-fonts) is given; off, the output depends on the
// given fonts alone when `system_fonts` is false too.
//
// `dpi`: pixels per inch of the physical units (in, cm, mm, pt, pc) everywhere in the document,
// its root width and height included, so it decides the document's pixel size (width="1in" is
// 300 pixels at 300 dpi); px and unitless lengths do not change. kMinDpi to kMaxDpi, else parsing
// throws Error(InvalidArgument). SVG images inside the document are read at the same resolution.
//
// `export_id`: when not empty, only the element with that id (a leading '#' is ignored) and its
// content are drawn, where they are in the whole document: its ancestors' transforms, viewports,
// inherited properties and group effects (opacity, clip-path, mask, filter) still apply, as if
// every other element were removed; the root's background-color is not drawn. What it references
// (gradients, patterns, clips, masks, markers, filters, use targets) still resolves through the
// whole document, and the document keeps its size: nothing is cropped. A part of a text (tspan,
// textPath) draws its whole text element. An element the document does not draw draws nothing;
// one the walk of the tree never reaches (inside defs, a clipPath, a mask, a pattern, a marker, a
// symbol, a display:none group) with a warning. An id that names no element makes parsing throw
// Error(InvalidData, "no element with id 'ID'") (load() adds " in PATH"). SVG images inside the
// document are drawn whole.
struct SvgOptions {
    static constexpr double kMinDpi = 1, kMaxDpi = 10000;
    std::string base_dir;
    std::string resource_root;
    int nesting = 0;  // SVG images nest at most Limits::svg_image_nesting deep
    std::vector<std::string> font_dirs, font_files;
    bool system_fonts = true;
    bool system_fallback = false;
    std::string font_family = "Times New Roman";
    std::string serif_family = "Times New Roman";
    std::string sans_serif_family = "Arial";
    std::string cursive_family = "Comic Sans MS";
    std::string fantasy_family = "Impact";
    std::string monospace_family = "Courier New";
    std::shared_ptr<const FontDatabase> font_database;
    double dpi = 96;
    std::string export_id;
    // The initial value of the `color` property: what currentColor means where the document sets
    // no colour. A host drawing the document inside something that has a colour of its own (an
    // OpenType SVG glyph inside text) sets it.
    Color color = Color::black();
    // What context-fill means outside `use` and markers (where it names their paint): none unless
    // set. An OpenType SVG glyph's context is its text, filled with `color`.
    std::optional<Color> context_fill;
};

class SvgDocument {
public:
    // Parses SVG text (or gzip-compressed SVG text: .svgz). Throws Error(Parse) for malformed XML,
    // Error(InvalidData) for an unusable root (missing size, negative or zero size), Error(Limit)
    // beyond the limits.
    static SvgDocument parse(std::string_view text, const SvgOptions& options = {});
    // Reads a file (.svg or .svgz); images resolve against the file's folder, and may not leave it
    // unless `resource_root` names a wider folder.
    static SvgDocument load(const std::string& path, const std::string& resource_root = {});
    // Same with options (fonts, resource_root); base_dir is set to the file's folder.
    static SvgDocument load(const std::string& path, const SvgOptions& options);

    SvgDocument(SvgDocument&&) noexcept;
    SvgDocument& operator=(SvgDocument&&) noexcept;
    ~SvgDocument();

    // Output size in pixels: the root's width and height (at SvgOptions::dpi) rounded to the
    // nearest whole pixel, at least 1 (resvg's rule). The fractional intrinsic size is kept for
    // scaling.
    int width() const;
    int height() const;
    double intrinsic_width() const;
    double intrinsic_height() const;
    // Output sizes for a requested width, height or zoom, the way resvg and rsvg-convert choose
    // them: the other side is ceil(requested x the rounded aspect ratio); a zoom multiplies the
    // rounded size and rounds up. So width="16.031" height="16" at width 256 is 256 x 256.
    // Throws Error(Limit) past the canvas limits.
    std::pair<int, int> output_size_for_width(int width) const;
    std::pair<int, int> output_size_for_height(int height) const;
    std::pair<int, int> output_size_for_zoom(double zoom) const;
    // Warnings collected while reading (unsupported features, recovered path-data errors).
    const std::vector<std::string>& warnings() const;

    // Draws the document with `base` (pixel transform) applied on top of the viewBox mapping.
    void render(Canvas& canvas, const Affine& base = {}) const;
    // A transparent Pixmap of width() x height() with the document drawn.
    Pixmap render() const;
    // A transparent Pixmap of width x height, the document scaled to fill it exactly (the
    // intrinsic size, fractional, maps onto the whole pixmap).
    Pixmap render_size(int width, int height) const;

private:
    struct Impl;
    explicit SvgDocument(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// Parses an SVG transform list ("translate(10 20) rotate(45)"). Throws Error(Parse).
Affine parse_svg_transform(std::string_view text);

// Installs the SVG reader as the text stage's drawer of OpenType SVG glyphs (casteljau/text.hpp,
// set_svg_glyph_drawer), so that draw_text draws fonts with an 'SVG ' table (Twitter Color Emoji
// and others) in their colours. SvgDocument::parse and load call it, and so does the casteljau
// command; a program drawing text without reading SVG calls it once before drawing. Each glyph
// document is read with export_id "glyphN" and no system fonts; currentColor and context-fill are
// the text's colour, as OpenType's SVG table asks. Converted glyph documents are cached per
// process (at most 512, by font, glyph and colour).
// Thread-safety: call it before drawing text on several threads.
void enable_svg_glyphs();

}  // namespace casteljau
