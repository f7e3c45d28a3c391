// Text stage, COLR v1 table reading (src/text/colr_table.hpp). Big-endian fields at checked
// offsets; a failed check makes the paint (or the list entry) absent.
#include "text/colr_table.hpp"

#include <cmath>

namespace casteljau::text_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A bounds-checked big-endian reader over the table.
struct Cursor {
    const std::vector<std::uint8_t>& d;
    std::size_t at;
    bool ok = true;

    std::uint32_t take(int bytes) {
        if (!ok || at + static_cast<std::size_t>(bytes) > d.size()) {
            ok = false;
            return 0;
        }
        std::uint32_t v = 0;
        for (int i = 0; i < bytes; ++i) v = v << 8 | d[at++];
        return v;
    }
    std::uint8_t u8() { return static_cast<std::uint8_t>(take(1)); }
    std::uint16_t u16() { return static_cast<std::uint16_t>(take(2)); }
    std::int16_t i16() { return static_cast<std::int16_t>(take(2)); }
    std::uint32_t u24() { return take(3); }
    std::uint32_t u32() { return take(4); }
    double f2dot14() { return i16() / 16384.0; }
    double fixed() { return static_cast<std::int32_t>(u32()) / 65536.0; }
};

Affine about(double cx, double cy, const Affine& m) {
    return Affine::translate(cx, cy) * m * Affine::translate(-cx, -cy);
}

}  // namespace

ColrTable::ColrTable(std::vector<std::uint8_t> bytes) : data_(std::move(bytes)) {
    Cursor c{data_, 0};
    const std::uint16_t version = c.u16();
    c.at = 14;  // after the version 0 header
    const std::uint32_t base = c.u32(), layers = c.u32(), clips = c.u32();
    if (!c.ok || version != 1) return;
    auto valid = [&](std::uint32_t o) { return o != 0 && o + 4 <= data_.size() ? o : 0u; };
    base_list_ = valid(base);
    layer_list_ = valid(layers);
    clip_list_ = valid(clips);
}

std::optional<std::size_t> ColrTable::root(std::uint32_t glyph) const {
    if (!base_list_) return std::nullopt;
    Cursor c{data_, base_list_};
    std::uint32_t lo = 0, hi = c.u32();
    if (!c.ok || hi > (data_.size() - base_list_ - 4) / 6) return std::nullopt;
    while (lo < hi) {  // records sorted by glyph id
        const std::uint32_t mid = lo + (hi - lo) / 2;
        Cursor r{data_, base_list_ + 4 + 6u * mid};
        const std::uint16_t id = r.u16();
        if (id < glyph)
            lo = mid + 1;
        else if (id > glyph)
            hi = mid;
        else {
            const std::uint32_t off = r.u32();
            if (!r.ok || off == 0 || base_list_ + off >= data_.size()) return std::nullopt;
            return base_list_ + off;
        }
    }
    return std::nullopt;
}

std::optional<std::size_t> ColrTable::layer(std::uint32_t index) const {
    if (!layer_list_) return std::nullopt;
    Cursor c{data_, layer_list_};
    const std::uint32_t count = c.u32();
    if (!c.ok || index >= count) return std::nullopt;
    c.at = layer_list_ + 4 + 4ull * index;
    const std::uint32_t off = c.u32();
    if (!c.ok || off == 0 || layer_list_ + off >= data_.size()) return std::nullopt;
    return layer_list_ + off;
}

std::optional<Rect> ColrTable::clip_box(std::uint32_t glyph) const {
    if (!clip_list_) return std::nullopt;
    Cursor c{data_, clip_list_};
    if (c.u8() != 1) return std::nullopt;
    const std::uint32_t count = c.u32();
    if (!c.ok || count > (data_.size() - clip_list_) / 7) return std::nullopt;
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint16_t first = c.u16(), last = c.u16();
        const std::uint32_t off = c.u24();
        if (!c.ok) return std::nullopt;
        if (glyph < first || glyph > last) continue;
        Cursor b{data_, clip_list_ + off};
        const std::uint8_t format = b.u8();
        const double x0 = b.i16(), y0 = b.i16(), x1 = b.i16(), y1 = b.i16();
        if (!b.ok || (format != 1 && format != 2)) return std::nullopt;
        return Rect{x0, y0, x1, y1};
    }
    return std::nullopt;
}

bool ColrTable::paint(std::size_t at, ColrPaint& out) const {
    out = ColrPaint{};
    Cursor c{data_, at};
    const std::uint8_t format = c.u8();
    const bool var = format >= 3 && format <= 31 && format % 2 == 1;  // variable forms: defaults only
    auto child = [&](std::size_t& slot) {
        const std::uint32_t off = c.u24();
        if (off == 0 || at + off >= data_.size()) c.ok = false;
        slot = at + off;
    };
    auto color_line = [&](ColrColorLine& line) {
        const std::uint32_t off = c.u24();
        if (off == 0) c.ok = false;
        Cursor l{data_, at + off};
        line.extend = l.u8();
        const std::uint16_t count = l.u16();
        const std::size_t size = var ? 10 : 6;  // VarColorStop adds a VarIndexBase
        if (!l.ok || count * size > data_.size() - l.at) c.ok = false;
        for (std::uint16_t i = 0; i < count && l.ok && c.ok; ++i) {
            ColrStop s;
            s.offset = l.f2dot14();
            s.palette_index = l.u16();
            s.alpha = l.f2dot14();
            if (var) l.u32();
            line.stops.push_back(s);
        }
        if (line.extend > 2) line.extend = 0;
    };
    auto point = [&] { return Point{static_cast<double>(c.i16()), static_cast<double>(c.i16())}; };
    switch (format) {
        case 1:
            out.kind = ColrPaint::Kind::Layers;
            out.layer_count = c.u8();
            out.first_layer = c.u32();
            break;
        case 2:
        case 3:
            out.kind = ColrPaint::Kind::Solid;
            out.palette_index = c.u16();
            out.alpha = c.f2dot14();
            break;
        case 4:
        case 5:
            out.kind = ColrPaint::Kind::Linear;
            color_line(out.line);
            out.p0 = point();
            out.p1 = point();
            out.p2 = point();
            break;
        case 6:
        case 7:
            out.kind = ColrPaint::Kind::Radial;
            color_line(out.line);
            out.p0 = point();
            out.r0 = c.u16();
            out.p1 = point();
            out.r1 = c.u16();
            break;
        case 8:
        case 9:
            out.kind = ColrPaint::Kind::Sweep;
            color_line(out.line);
            out.p0 = point();
            // Half turns with a bias of one half turn, so that 360 degrees can be written.
            out.start_angle = (c.f2dot14() + 1) * 180;
            out.end_angle = (c.f2dot14() + 1) * 180;
            break;
        case 10:
            out.kind = ColrPaint::Kind::Glyph;
            child(out.child);
            out.glyph = c.u16();
            break;
        case 11:
            out.kind = ColrPaint::Kind::ColrGlyph;
            out.glyph = c.u16();
            break;
        case 12:
        case 13: {
            out.kind = ColrPaint::Kind::Transform;
            child(out.child);
            const std::uint32_t off = c.u24();
            Cursor m{data_, at + off};
            const double xx = m.fixed(), yx = m.fixed(), xy = m.fixed(), yy = m.fixed(), dx = m.fixed(), dy = m.fixed();
            if (!m.ok || off == 0) c.ok = false;
            out.transform = Affine{xx, yx, xy, yy, dx, dy};
            break;
        }
        case 14:
        case 15: {
            out.kind = ColrPaint::Kind::Transform;
            child(out.child);
            const double dx = c.i16(), dy = c.i16();
            out.transform = Affine::translate(dx, dy);
            break;
        }
        case 16:
        case 17:
        case 18:
        case 19:
        case 20:
        case 21:
        case 22:
        case 23: {
            out.kind = ColrPaint::Kind::Transform;
            child(out.child);
            const bool uniform = format >= 20;
            const bool centred = format == 18 || format == 19 || format == 22 || format == 23;
            const double sx = c.f2dot14(), sy = uniform ? sx : c.f2dot14();
            const double cx = centred ? c.i16() : 0, cy = centred ? c.i16() : 0;
            out.transform = about(cx, cy, Affine::scale(sx, sy));
            break;
        }
        case 24:
        case 25:
        case 26:
        case 27: {
            out.kind = ColrPaint::Kind::Transform;
            child(out.child);
            const double angle = c.f2dot14() * kPi;  // counter-clockwise, half turns per unit
            const double cx = format >= 26 ? c.i16() : 0, cy = format >= 26 ? c.i16() : 0;
            out.transform = about(cx, cy, Affine::rotate(angle));
            break;
        }
        case 28:
        case 29:
        case 30:
        case 31: {
            out.kind = ColrPaint::Kind::Transform;
            child(out.child);
            const double ax = c.f2dot14() * kPi, ay = c.f2dot14() * kPi;
            const double cx = format >= 30 ? c.i16() : 0, cy = format >= 30 ? c.i16() : 0;
            out.transform = about(cx, cy, Affine{1, std::tan(ay), -std::tan(ax), 1, 0, 0});
            break;
        }
        case 32:
            out.kind = ColrPaint::Kind::Composite;
            child(out.child);
            out.mode = c.u8();
            child(out.backdrop);
            break;
        default: return false;
    }
    return c.ok;
}

}  // namespace casteljau::text_detail
