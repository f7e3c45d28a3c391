// Internal (formats): SVG values. Reads the small value syntaxes of SVG attributes and
// properties (lengths with units, numbers, opacities, viewBox, preserveAspectRatio) and holds the
// viewport size lengths resolve against.
// Coordinates: user units. Thread-safety: plain functions and values.
#pragma once

#include <cmath>
#include <optional>
#include <string_view>

#include "casteljau/geometry.hpp"

namespace casteljau::svg {

// The size, in user units, of the nearest viewport (the root svg, a nested svg, a symbol, a
// marker or pattern content): percentages of x and width are of `w`, of y and height of `h`,
// and of other lengths (a radius, stroke-width) of the normalised diagonal.
struct Viewport {
    double w = 100, h = 100;
    double diagonal() const { return std::sqrt((w * w + h * h) / 2); }
};

// `s` without leading and trailing white space.
std::string_view trim(std::string_view s);

// A length with an optional unit; percentages resolve against `percent_of`, em against
// `font_size` and ex against half of it (as resvg: no x-height from the font), the physical units
// (in, cm, mm, pt, pc) against `dpi` pixels per inch (SvgOptions::dpi). nullopt when invalid.
std::optional<double> parse_length(std::string_view text, double percent_of, double font_size, double dpi);

// The font size em and ex are relative to where no element's font size is known.
constexpr double kUnknownFontSize = 16;

// A plain number (a leading '+' allowed, nothing after it); nullopt when invalid or not finite.
std::optional<double> parse_number(std::string_view text);

// Opacity values: a number or a percentage, clamped to [0, 1].
std::optional<double> parse_opacity(std::string_view text);

// A viewBox "x y w h" (commas or spaces); nullopt when absent or invalid (w or h not positive).
std::optional<Rect> parse_viewbox(std::string_view text);

// The viewBox -> viewport (0, 0, w, h) mapping under preserveAspectRatio
// "[defer] <none | x{Min,Mid,Max}Y{Min,Mid,Max}> [meet | slice]" (default xMidYMid meet; an
// invalid value is the default).
Affine viewbox_transform(const Rect& vb, std::string_view par, double w, double h);

}  // namespace casteljau::svg
