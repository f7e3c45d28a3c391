// Text stage, COLR glyphs: v1 paint graphs and v0 layers drawn through the Canvas
// (src/text/color_glyphs.hpp).
//
// The v1 paint graph (read by src/text/colr_table.cpp; every value in font units) is walked:
// PaintColrLayers paints its layers in order; PaintGlyph fills the glyph's outline with its child
// (directly for a solid colour or a linear or radial gradient, else by clipping to the outline);
// transforms concatenate onto the Canvas transform; PaintColrGlyph paints another base glyph inside
// its clip box; PaintComposite paints the backdrop into a layer and the source into a nested layer
// composited with the mode. Sweep gradients, which the paint stage has no shader for, are computed
// per pixel of the clip rectangle and drawn as an image. v0 layers come from FreeType
// (FT_Get_Color_Glyph_Layer), each filled with its palette colour.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_COLOR_H
#include FT_TRUETYPE_TABLES_H

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "casteljau/error.hpp"
#include "casteljau/shader.hpp"
#include "text/color_glyphs.hpp"
#include "text/colr_table.hpp"
#include "text/font_impl.hpp"

namespace casteljau::text_detail {

namespace {

// Limits against malformed fonts: nesting depth (a cyclic graph), paints per glyph and stops per
// colour line.
constexpr int kMaxDepth = 32;
constexpr int kMaxPaints = 4096;
constexpr int kMaxStops = 256;

constexpr double kPi = 3.14159265358979323846;

BlendMode composite_mode(int m) {
    switch (m) {
        case FT_COLR_COMPOSITE_CLEAR: return BlendMode::Clear;
        case FT_COLR_COMPOSITE_SRC: return BlendMode::Source;
        case FT_COLR_COMPOSITE_DEST: return BlendMode::Destination;
        case FT_COLR_COMPOSITE_DEST_OVER: return BlendMode::DestinationOver;
        case FT_COLR_COMPOSITE_SRC_IN: return BlendMode::SourceIn;
        case FT_COLR_COMPOSITE_DEST_IN: return BlendMode::DestinationIn;
        case FT_COLR_COMPOSITE_SRC_OUT: return BlendMode::SourceOut;
        case FT_COLR_COMPOSITE_DEST_OUT: return BlendMode::DestinationOut;
        case FT_COLR_COMPOSITE_SRC_ATOP: return BlendMode::SourceAtop;
        case FT_COLR_COMPOSITE_DEST_ATOP: return BlendMode::DestinationAtop;
        case FT_COLR_COMPOSITE_XOR: return BlendMode::Xor;
        case FT_COLR_COMPOSITE_PLUS: return BlendMode::Plus;
        case FT_COLR_COMPOSITE_SCREEN: return BlendMode::Screen;
        case FT_COLR_COMPOSITE_OVERLAY: return BlendMode::Overlay;
        case FT_COLR_COMPOSITE_DARKEN: return BlendMode::Darken;
        case FT_COLR_COMPOSITE_LIGHTEN: return BlendMode::Lighten;
        case FT_COLR_COMPOSITE_COLOR_DODGE: return BlendMode::ColorDodge;
        case FT_COLR_COMPOSITE_COLOR_BURN: return BlendMode::ColorBurn;
        case FT_COLR_COMPOSITE_HARD_LIGHT: return BlendMode::HardLight;
        case FT_COLR_COMPOSITE_SOFT_LIGHT: return BlendMode::SoftLight;
        case FT_COLR_COMPOSITE_DIFFERENCE: return BlendMode::Difference;
        case FT_COLR_COMPOSITE_EXCLUSION: return BlendMode::Exclusion;
        case FT_COLR_COMPOSITE_MULTIPLY: return BlendMode::Multiply;
        case FT_COLR_COMPOSITE_HSL_HUE: return BlendMode::Hue;
        case FT_COLR_COMPOSITE_HSL_SATURATION: return BlendMode::Saturation;
        case FT_COLR_COMPOSITE_HSL_COLOR: return BlendMode::Color;
        case FT_COLR_COMPOSITE_HSL_LUMINOSITY: return BlendMode::Luminosity;
        default: return BlendMode::SourceOver;
    }
}

SpreadMethod spread_of(int extend) {
    return extend == 1 ? SpreadMethod::Repeat : extend == 2 ? SpreadMethod::Reflect : SpreadMethod::Pad;
}

// The font's COLR table, read once and kept in the Font.
const ColrTable& colr_table(const Font& font) {
    Font::Impl& fi = font.impl();
    if (!fi.colr_table) {
        std::vector<std::uint8_t> bytes;
        FT_ULong length = 0;
        const FT_ULong tag = FT_MAKE_TAG('C', 'O', 'L', 'R');
        if (FT_Load_Sfnt_Table(fi.face, tag, 0, nullptr, &length) == 0 && length > 0) {
            bytes.resize(length);
            if (FT_Load_Sfnt_Table(fi.face, tag, 0, bytes.data(), &length) != 0) bytes.clear();
        }
        fi.colr_table = std::make_shared<ColrTable>(std::move(bytes));
    }
    return *static_cast<const ColrTable*>(fi.colr_table.get());
}

struct Walker {
    const Font& font;
    const ColrTable& table;
    const std::vector<Color>* palette = nullptr;
    Color foreground;
    int paints = 0;

    bool get(std::size_t at, ColrPaint& out) {
        if (++paints > kMaxPaints) return false;
        return table.paint(at, out);
    }

    Color color_of(std::uint16_t index, double alpha) const {
        Color c = Color::transparent();
        if (index == 0xffff)
            c = foreground;
        else if (palette && index < palette->size())
            c = (*palette)[index];
        return c.with_opacity(std::clamp(alpha, 0.0, 1.0));
    }

    // The colour line's stops with offsets mapped from [lo, hi] to [0, 1]; lo == hi for one stop.
    std::vector<GradientStop> stops(const ColrColorLine& line, double& lo, double& hi) const {
        std::vector<std::pair<double, Color>> raw;
        for (const ColrStop& s : line.stops) {
            if (raw.size() >= static_cast<std::size_t>(kMaxStops)) break;
            raw.emplace_back(s.offset, color_of(s.palette_index, s.alpha));
        }
        std::stable_sort(raw.begin(), raw.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<GradientStop> out;
        if (raw.empty()) return out;
        lo = raw.front().first;
        hi = raw.back().first;
        const double span = hi - lo;
        for (const auto& [o, c] : raw) out.push_back({span > 0 ? (o - lo) / span : 0.0, c});
        return out;
    }

    // A Paint for a solid colour or a linear or radial gradient in the current paint space; false
    // for other paints.
    bool simple_paint(const ColrPaint& p, Paint& out) const {
        double lo = 0, hi = 1;
        switch (p.kind) {
            case ColrPaint::Kind::Solid: out = Paint::solid(color_of(p.palette_index, p.alpha)); return true;
            case ColrPaint::Kind::Linear: {
                std::vector<GradientStop> st = stops(p.line, lo, hi);
                if (st.empty()) return false;
                const Point p0 = p.p0, p1 = p.p1, p2 = p.p2;
                // Colours are constant along p0-p2: the gradient runs from p0 along the normal of
                // p0-p2 to the projection of p1 on it.
                const Point n{-(p2.y - p0.y), p2.x - p0.x};
                const double nn = n.x * n.x + n.y * n.y;
                Point q1 = p1;
                if (nn > 0) {
                    const double t = ((p1.x - p0.x) * n.x + (p1.y - p0.y) * n.y) / nn;
                    q1 = {p0.x + t * n.x, p0.y + t * n.y};
                }
                const Point a{p0.x + lo * (q1.x - p0.x), p0.y + lo * (q1.y - p0.y)};
                Point b{p0.x + hi * (q1.x - p0.x), p0.y + hi * (q1.y - p0.y)};
                if (a.x == b.x && a.y == b.y) b.x += 1e-6;
                out = Paint::shaded(Shader::linear(a, b, std::move(st), spread_of(p.line.extend)));
                return true;
            }
            case ColrPaint::Kind::Radial: {
                std::vector<GradientStop> st = stops(p.line, lo, hi);
                if (st.empty()) return false;
                auto circle_at = [&](double t, Point& c, double& r) {
                    c = {p.p0.x + t * (p.p1.x - p.p0.x), p.p0.y + t * (p.p1.y - p.p0.y)};
                    r = p.r0 + t * (p.r1 - p.r0);
                };
                Point ca, cb;
                double ra = 0, rb = 0;
                circle_at(lo, ca, ra);
                circle_at(hi, cb, rb);
                out = Paint::shaded(Shader::radial(cb, std::max(rb, 0.0), ca, std::max(ra, 0.0), std::move(st),
                                                   spread_of(p.line.extend)));
                return true;
            }
            default: return false;
        }
    }

    // The device pixels of the current clip, as a Rect.
    static Rect clip_rect(const Canvas& canvas) {
        const IRect& c = canvas.clip();
        return {static_cast<double>(c.x0), static_cast<double>(c.y0), static_cast<double>(c.x1),
                static_cast<double>(c.y1)};
    }

    // Fills the whole clip with `paint`, whose shader is in the current paint space.
    static void fill_clip(Canvas& canvas, Paint paint) {
        if (paint.shader) paint.shader = std::make_shared<const Shader>(paint.shader->transformed(canvas.transform()));
        canvas.save();
        canvas.reset_transform();
        canvas.fill_rect(clip_rect(canvas), paint);
        canvas.restore();
    }

    void sweep(Canvas& canvas, const ColrPaint& g) const {
        double lo = 0, hi = 1;
        std::vector<GradientStop> st = stops(g.line, lo, hi);
        if (st.empty()) return;
        const IRect& clip = canvas.clip();
        if (clip.empty()) return;
        const Affine& m = canvas.transform();
        const double det = m.a * m.d - m.b * m.c;
        if (!(std::abs(det) > 1e-12)) return;
        const Affine inv{
            m.d / det, -m.b / det, -m.c / det, m.a / det, (m.c * m.f - m.d * m.e) / det, (m.b * m.e - m.a * m.f) / det};
        const Point c = g.p0;
        // Angles in degrees, counter-clockwise from the x axis; the colour line spans [start, end].
        const double a0 = g.start_angle + lo * (g.end_angle - g.start_angle);
        const double a1 = g.start_angle + hi * (g.end_angle - g.start_angle);
        const Shader line = Shader::linear({0, 0}, {1, 0}, std::move(st), spread_of(g.line.extend));
        Pixmap image(clip.width(), clip.height());
        for (int y = 0; y < clip.height(); ++y) {
            std::uint8_t* row = image.row(y);
            for (int x = 0; x < clip.width(); ++x) {
                const Point p = inv.apply({clip.x0 + x + 0.5, clip.y0 + y + 0.5});
                double angle = std::atan2(p.y - c.y, p.x - c.x) * 180.0 / kPi;
                if (angle < 0) angle += 360.0;
                const double t = a1 != a0 ? (angle - a0) / (a1 - a0) : (angle < a0 ? 0.0 : 1.0);
                float rgba[4];
                line.color_at(t, rgba);
                auto byte = [](float v) {
                    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
                };
                const PremulPixel px =
                    premultiply(Color::rgba(byte(rgba[0]), byte(rgba[1]), byte(rgba[2]), byte(rgba[3])));
                row[4 * x] = px.r;
                row[4 * x + 1] = px.g;
                row[4 * x + 2] = px.b;
                row[4 * x + 3] = px.a;
            }
        }
        canvas.save();
        canvas.reset_transform();
        canvas.draw_image(image, Affine::translate(clip.x0, clip.y0), ImageSampling::Nearest);
        canvas.restore();
    }

    Path outline(std::uint32_t glyph) const {
        try {
            return font.glyph_path(glyph);
        } catch (const Error&) { return {}; }
    }

    void clip_box(Canvas& canvas, std::uint32_t glyph) const {
        const std::optional<Rect> box = table.clip_box(glyph);
        if (!box) return;
        Path p;
        p.move_to({box->x0, box->y0});
        p.line_to({box->x0, box->y1});
        p.line_to({box->x1, box->y1});
        p.line_to({box->x1, box->y0});
        p.close();
        canvas.clip_path(p);
    }

    void paint(Canvas& canvas, std::size_t at, int depth) {
        ColrPaint p;
        if (depth > kMaxDepth || !get(at, p)) return;
        Paint simple;
        switch (p.kind) {
            case ColrPaint::Kind::Transform:
                canvas.save();
                canvas.concat(p.transform);
                paint(canvas, p.child, depth + 1);
                canvas.restore();
                return;
            case ColrPaint::Kind::Layers:
                for (std::uint32_t i = 0; i < p.layer_count && paints < kMaxPaints; ++i)
                    if (const auto layer = table.layer(p.first_layer + i)) paint(canvas, *layer, depth + 1);
                return;
            case ColrPaint::Kind::Glyph: {
                const Path shape = outline(p.glyph);
                if (shape.empty()) return;
                ColrPaint c;
                if (get(p.child, c) && simple_paint(c, simple)) {
                    canvas.fill_path(shape, simple, FillRule::NonZero);
                    return;
                }
                canvas.save();
                canvas.clip_path(shape);
                paint(canvas, p.child, depth + 1);
                canvas.restore();
                return;
            }
            case ColrPaint::Kind::Solid:
            case ColrPaint::Kind::Linear:
            case ColrPaint::Kind::Radial:
                if (simple_paint(p, simple)) fill_clip(canvas, simple);
                return;
            case ColrPaint::Kind::Sweep: sweep(canvas, p); return;
            case ColrPaint::Kind::ColrGlyph: {
                const auto root = table.root(p.glyph);
                if (!root) return;
                canvas.save();
                clip_box(canvas, p.glyph);
                paint(canvas, *root, depth + 1);
                canvas.restore();
                return;
            }
            case ColrPaint::Kind::Composite:
                canvas.begin_layer();
                paint(canvas, p.backdrop, depth + 1);
                canvas.begin_layer(1.0, composite_mode(p.mode));
                paint(canvas, p.child, depth + 1);
                canvas.end_layer();
                canvas.end_layer();
                return;
            default: return;
        }
    }

    // Bounds (font units) of what the paint at `at` draws under `m`; `unbounded` is set for a
    // paint not inside any PaintGlyph.
    void bounds(std::size_t at, const Affine& m, int depth, Rect& box, bool& have, bool& unbounded) {
        ColrPaint p;
        if (depth > kMaxDepth || !get(at, p)) return;
        switch (p.kind) {
            case ColrPaint::Kind::Transform: bounds(p.child, m * p.transform, depth + 1, box, have, unbounded); return;
            case ColrPaint::Kind::Layers:
                for (std::uint32_t i = 0; i < p.layer_count && paints < kMaxPaints; ++i)
                    if (const auto layer = table.layer(p.first_layer + i))
                        bounds(*layer, m, depth + 1, box, have, unbounded);
                return;
            case ColrPaint::Kind::Glyph: {
                const Path shape = outline(p.glyph);
                for (Point q : shape.points()) {
                    const Point r = m.apply(q);
                    if (!have)
                        box = {r.x, r.y, r.x, r.y};
                    else
                        box.include(r);
                    have = true;
                }
                return;
            }
            case ColrPaint::Kind::ColrGlyph:
                if (const auto root = table.root(p.glyph)) bounds(*root, m, depth + 1, box, have, unbounded);
                return;
            case ColrPaint::Kind::Composite:
                bounds(p.backdrop, m, depth + 1, box, have, unbounded);
                bounds(p.child, m, depth + 1, box, have, unbounded);
                return;
            default: unbounded = true; return;
        }
    }
};

}  // namespace

bool has_colr_paint_graph(const Font& font, std::uint32_t glyph) { return colr_table(font).root(glyph).has_value(); }

bool paint_colr_glyph(Canvas& canvas, const Font& font, std::uint32_t glyph, const std::vector<Color>& palette,
                      Color foreground) {
    Walker w{font, colr_table(font), &palette, foreground};
    if (const auto root = w.table.root(glyph)) {
        canvas.save();
        w.clip_box(canvas, glyph);
        w.paint(canvas, *root, 0);
        canvas.restore();
        return true;
    }
    FT_Face face = font.impl().face;
    FT_LayerIterator it{};
    it.p = nullptr;
    FT_UInt layer = 0, color = 0;
    bool any = false;
    for (int n = 0; n < kMaxPaints && FT_Get_Color_Glyph_Layer(face, glyph, &layer, &color, &it); ++n) {
        any = true;
        const Path shape = w.outline(layer);
        if (!shape.empty())
            canvas.fill_path(shape, Paint::solid(w.color_of(static_cast<std::uint16_t>(color), 1.0)),
                             FillRule::NonZero);
    }
    return any;
}

Rect colr_glyph_bounds(const Font& font, std::uint32_t glyph) {
    Walker w{font, colr_table(font), nullptr, Color::black()};
    Rect box;
    bool have = false, unbounded = false;
    if (const auto root = w.table.root(glyph)) {
        if (const auto clip = w.table.clip_box(glyph)) return *clip;
        w.bounds(*root, Affine{}, 0, box, have, unbounded);
    } else {
        FT_LayerIterator it{};
        it.p = nullptr;
        FT_UInt layer = 0, color = 0;
        for (int n = 0; n < kMaxPaints && FT_Get_Color_Glyph_Layer(font.impl().face, glyph, &layer, &color, &it); ++n) {
            const Path shape = w.outline(layer);
            for (Point q : shape.points()) {
                if (!have)
                    box = {q.x, q.y, q.x, q.y};
                else
                    box.include(q);
                have = true;
            }
        }
    }
    if (unbounded) {
        const FontMetrics& fm = font.metrics();
        const Rect em{0, fm.descender, static_cast<double>(fm.units_per_em), fm.ascender};
        box = have ? box.united(em) : em;
        have = true;
    }
    return have ? box : Rect{};
}

}  // namespace casteljau::text_detail
