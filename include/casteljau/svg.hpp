// casteljau/svg.hpp: an SVG reader that draws onto a Canvas.
//
// Supported now: the root <svg> width/height (px or unitless; percentages and physical units
// are converted at 96 dpi) and viewBox with preserveAspectRatio; <g> with transform and inherited
// presentation attributes; <path>, <rect>, <circle>, <ellipse>, <line>, <polyline>, <polygon>;
// fill (colour or none), fill-rule, fill-opacity, opacity on shapes, the style attribute;
// transform lists (matrix, translate, scale, rotate, skewX, skewY). Unknown elements are skipped.
// SVG coordinates: user units, y down, mapped to pixels by the viewBox transform.
// Limits: element nesting depth limits::kMaxNestingDepth; canvas size as for Pixmap.
// Thread-safety: SvgDocument is an immutable value after parsing; render from any thread.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "casteljau/canvas.hpp"
#include "casteljau/paint.hpp"

namespace casteljau {

class SvgDocument {
public:
    // Parses SVG text. Throws Error(Parse) for malformed XML, Error(InvalidData) for an unusable
    // root (missing size, negative or zero size), Error(Limit) beyond the limits.
    static SvgDocument parse(std::string_view text);
    static SvgDocument load(const std::string& path);

    SvgDocument(SvgDocument&&) noexcept;
    SvgDocument& operator=(SvgDocument&&) noexcept;
    ~SvgDocument();

    // Output size in pixels (the root's width and height, rounded up to whole pixels).
    int width() const;
    int height() const;
    // Warnings collected while reading (unsupported features, recovered path-data errors).
    const std::vector<std::string>& warnings() const;

    // Draws the document with `base` (pixel transform) applied on top of the viewBox mapping.
    void render(Canvas& canvas, const Affine& base = {}) const;
    // A transparent Pixmap of width() x height() with the document drawn.
    Pixmap render() const;

private:
    struct Impl;
    explicit SvgDocument(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// Parses an SVG transform list ("translate(10 20) rotate(45)"). Throws Error(Parse).
Affine parse_svg_transform(std::string_view text);

}  // namespace casteljau
