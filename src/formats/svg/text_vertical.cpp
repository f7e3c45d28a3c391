// Formats stage, SVG text layout: vertical text (text_clusters.hpp). As resvg lays it out, and
// as browsers do for fonts without vertical metrics: clusters are shaped horizontally and the
// line is turned 90 degrees clockwise about its start; characters of vertical orientation U
// (UAX #50) are turned back upright about the middle of their advance.
#include "formats/svg/text_clusters.hpp"

namespace casteljau::svg_text {

namespace {

// Punctuation of the CJK Symbols and Punctuation block that Unicode's vertical orientation
// (UAX #50) marks Tu or Tr: set in vertical text by a vertical alternate glyph, which for these
// (the ideographic comma and full stop, brackets, the wave dash, the prolonged sound mark) is the
// horizontal glyph turned, as resvg draws them: they are turned sideways.
bool is_turned_punctuation(char32_t c) {
    return (c >= 0x3001 && c <= 0x3002) || (c >= 0x3008 && c <= 0x3011) || (c >= 0x3014 && c <= 0x301f) ||
           c == 0x3030 || c == 0x30a0 || c == 0x30fc;
}

}  // namespace

// Characters set upright in vertical text (CJK, kana, hangul, full-width forms, emoji); others
// are turned sideways (Unicode's vertical orientation U and Tu, approximately).
bool is_upright(char32_t c) {
    if (is_turned_punctuation(c)) return false;
    return (c >= 0x1100 && c <= 0x11ff) || (c >= 0x2e80 && c <= 0xa4cf) || (c >= 0xac00 && c <= 0xd7af) ||
           (c >= 0xf900 && c <= 0xfaff) || (c >= 0xfe30 && c <= 0xfe4f) || (c >= 0xff00 && c <= 0xffef) ||
           (c >= 0x1f000 && c <= 0x1faff) || (c >= 0x20000 && c <= 0x3ffff);
}

namespace {

// The rotate value of cluster `g`'s first character, as a rotation.
Affine cluster_rotation(const TextInput& in, const Cluster& g) {
    return g.ch < in.pos.size() && in.pos[g.ch].rotate ? Affine::rotate_degrees(*in.pos[g.ch].rotate) : Affine();
}

// The frame of vertical text's line at cluster `g`: the horizontal frame turned 90 degrees
// clockwise about the pen, moved by `mid` less the baseline shift (positive toward the left)
// and turned by the cluster's rotate.
Affine vertical_line_transform(const TextInput& in, const Cluster& g, double shift, double mid = 0) {
    return Affine::translate(g.x, g.y) * Affine::rotate_degrees(90) * Affine::translate(0, mid - shift) *
           cluster_rotation(in, g);
}

// Half the ascender plus descender of cluster `g`'s font: how far vertical text moves a sideways
// cluster's baseline so that its em box is centred on the line.
double vertical_mid(const TextInput& in, const Cluster& g) {
    if (!g.font) return 0;
    const FontMetrics& m = g.font->metrics();
    return (m.ascender + m.descender) / 2 * in.spans[g.span].font.size / m.units_per_em;
}

}  // namespace

// Cluster space -> user space for cluster `g` of vertical text, shaped horizontally as resvg
// does. The line runs down from the pen; in the line's frame (the horizontal frame turned 90
// degrees clockwise) the cluster's em box is centred on the line (its baseline moved by half
// the ascender plus descender). Sideways clusters stay turned; upright ones (CJK) turn back
// about the centre of their advance, so that their horizontal advance is the vertical step and
// the middle of their ascender-to-descender box sits on the line. rotate turns the cluster about
// its origin.
Affine vertical_cluster_transform(const TextInput& in, const Cluster& g, double shift) {
    const double mid = vertical_mid(in, g);
    if (!g.upright) return vertical_line_transform(in, g, shift, mid);
    const double half = g.advance / 2;
    return vertical_line_transform(in, g, shift) * Affine::translate(half, 0) * Affine::rotate_degrees(-90) *
           Affine::translate(-half, mid);
}

Affine vertical_on_path(const TextInput& in, const Cluster& g) {
    const double mid = vertical_mid(in, g);
    if (!g.upright) return Affine::translate(0, mid);
    const double half = g.advance / 2;
    return Affine::translate(half, 0) * Affine::rotate_degrees(-90) * Affine::translate(-half, mid);
}

// A run goes on in the frame its first cluster set.
Affine VerticalDecorationFrames::frame(const TextInput& in, const Cluster& g, double shift) {
    const CharPos none;
    const CharPos& p = g.ch < in.pos.size() ? in.pos[g.ch] : none;
    const bool moved = (p.rotate && *p.rotate != 0) || (p.dx && *p.dx != 0) || (p.dy && *p.dy != 0);
    if (g.span != span_ || moved) centred_ = !g.upright;
    span_ = g.span;
    return vertical_line_transform(in, g, shift, centred_ ? vertical_mid(in, g) : 0);
}

}  // namespace casteljau::svg_text
