// casteljau/blend_mode.hpp: how a painted colour combines with what is already there (paint stage).
//
// Two families, one enum: the W3C Compositing and Blending Level 1 blend modes (separable:
// multiply .. exclusion; non-separable: hue, saturation, color, luminosity), which blend the
// straight colours with B(Cb, Cs) and then composite source-over,
//   co = cs (1 - ab) + cb (1 - as) + as ab B(Cb, Cs),   ao = as + ab - as ab  (premultiplied c),
// and the twelve Porter-Duff operators, co = Fa cs + Fb cb, ao = Fa as + Fb ab with
//   Clear (0, 0), Source (1, 0), Destination (0, 1), SourceOver (1, 1 - as), DestinationOver (1 - ab, 1),
//   SourceIn (ab, 0), DestinationIn (0, as), SourceOut (1 - ab, 0), DestinationOut (0, 1 - as),
//   SourceAtop (ab, 1 - as), DestinationAtop (1 - ab, as), Xor (1 - ab, 1 - as),
// plus Plus (co = min(1, cs + cb), ao = min(1, as + ab)). Normal and SourceOver are the same mode.
// Colour values are sRGB, channels in [0, 1]. Thread-safety: pure functions.
#pragma once

#include <string_view>

namespace casteljau {

enum class BlendMode {
    Normal,
    Multiply,
    Screen,
    Overlay,
    Darken,
    Lighten,
    ColorDodge,
    ColorBurn,
    HardLight,
    SoftLight,
    Difference,
    Exclusion,
    Hue,
    Saturation,
    Color,
    Luminosity,
    // Porter-Duff operators (Normal is source-over).
    Clear,
    Source,
    Destination,
    DestinationOver,
    SourceIn,
    DestinationIn,
    SourceOut,
    DestinationOut,
    SourceAtop,
    DestinationAtop,
    Xor,
    Plus,
    SourceOver = Normal,
};
inline constexpr int kBlendModeCount = static_cast<int>(BlendMode::Plus) + 1;

// Parses the CSS mix-blend-mode names (normal, multiply, ..., color-dodge, ..., luminosity);
// false when unknown.
bool parse_blend_mode(std::string_view name, BlendMode& out);
// Parses every name: the CSS blend modes except "normal", and the Porter-Duff names of the
// Canvas 2D API and Compositing spec (clear, copy, source-over, destination-over, source-in,
// destination-in, source-out, destination-out, source-atop, destination-atop, xor,
// lighter/plus-lighter; "source" and "destination" too); false when unknown.
bool parse_blend_operator(std::string_view name, BlendMode& out);
// The name parse_blend_operator (or, for CSS modes, parse_blend_mode) reads back.
std::string_view blend_mode_name(BlendMode mode);
// True for the twelve Porter-Duff operators and Normal/SourceOver.
bool is_porter_duff(BlendMode mode);

// The blended straight colour B(cb, cs) of one pixel, channels in [0, 1], for the CSS blend modes
// (a Porter-Duff operator gives cs) (for tests and callers that blend themselves).
void blend_colors(BlendMode mode, const float cb[3], const float cs[3], float out[3]);
// The complete result of `mode` for one premultiplied pixel: source s, destination d (RGBA in
// [0, 1], premultiplied), out = the premultiplied result before coverage.
void blend_pixel(BlendMode mode, const float s[4], const float d[4], float out[4]);

}  // namespace casteljau
