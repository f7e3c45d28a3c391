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

// Reads the fields of the paint at `at` after its format byte. Offsets are relative to the paint;
// a field out of bounds, or a child offset that is 0 or leaves the table, clears c.ok.
struct PaintReader {
    const std::vector<std::uint8_t>& d;
    std::size_t at;
    Cursor c;
    bool variable = false;  // a variable form: its defaults are read, its VarIndexBase skipped

    // A child paint: a 24-bit offset, stored as a table offset in `slot`.
    void child(std::size_t& slot) {
        const std::uint32_t off = c.u24();
        if (off == 0 || at + off >= d.size()) c.ok = false;
        slot = at + off;
    }

    Point point() {
        const double x = c.i16(), y = c.i16();
        return {x, y};
    }

    // The ColorLine at a 24-bit offset: its extend mode and stops.
    void color_line(ColrColorLine& line) {
        const std::uint32_t off = c.u24();
        if (off == 0) c.ok = false;
        Cursor l{d, at + off};
        line.extend = l.u8();
        const std::uint16_t count = l.u16();
        const std::size_t size = variable ? 10 : 6;  // VarColorStop adds a VarIndexBase
        if (!l.ok || count * size > d.size() - l.at) c.ok = false;
        for (std::uint16_t i = 0; i < count && l.ok && c.ok; ++i) {
            ColrStop s;
            s.offset = l.f2dot14();
            s.palette_index = l.u16();
            s.alpha = l.f2dot14();
            if (variable) l.u32();
            line.stops.push_back(s);
        }
        if (line.extend > 2) line.extend = 0;
    }

    // Formats 4 to 9: linear, radial and sweep gradients.
    void gradient(std::uint8_t format, ColrPaint& out) {
        color_line(out.line);
        out.p0 = point();
        if (format <= 5) {
            out.kind = ColrPaint::Kind::Linear;
            out.p1 = point();
            out.p2 = point();
        } else if (format <= 7) {
            out.kind = ColrPaint::Kind::Radial;
            out.r0 = c.u16();
            out.p1 = point();
            out.r1 = c.u16();
        } else {
            out.kind = ColrPaint::Kind::Sweep;
            // Half turns with a bias of one half turn, so that 360 degrees can be written.
            out.start_angle = (c.f2dot14() + 1) * 180;
            out.end_angle = (c.f2dot14() + 1) * 180;
        }
    }

    // Formats 12 to 31, after the child offset: the transform from child to parent space.
    Affine transform(std::uint8_t format) {
        if (format <= 13) {  // an Affine2x3 table at a 24-bit offset
            const std::uint32_t off = c.u24();
            Cursor m{d, at + off};
            const double xx = m.fixed(), yx = m.fixed(), xy = m.fixed(), yy = m.fixed(), dx = m.fixed(), dy = m.fixed();
            if (!m.ok || off == 0) c.ok = false;
            return Affine{xx, yx, xy, yy, dx, dy};
        }
        if (format <= 15) {
            const double dx = c.i16(), dy = c.i16();
            return Affine::translate(dx, dy);
        }
        Affine m;
        bool centred;
        if (format <= 23) {  // scale: per axis (16 to 19) or uniform (20 to 23)
            const double sx = c.f2dot14(), sy = format >= 20 ? sx : c.f2dot14();
            m = Affine::scale(sx, sy);
            centred = format == 18 || format == 19 || format == 22 || format == 23;
        } else if (format <= 27) {
            m = Affine::rotate(c.f2dot14() * kPi);  // counter-clockwise, half turns per unit
            centred = format >= 26;
        } else {
            const double ax = c.f2dot14() * kPi, ay = c.f2dot14() * kPi;
            m = Affine{1, std::tan(ay), -std::tan(ax), 1, 0, 0};
            centred = format >= 30;
        }
        const double cx = centred ? c.i16() : 0, cy = centred ? c.i16() : 0;
        return about(cx, cy, m);
    }
};

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
    PaintReader r{data_, at, Cursor{data_, at}};
    const std::uint8_t format = r.c.u8();
    r.variable = format >= 3 && format <= 31 && format % 2 == 1;
    if (format == 0 || format > 32) return false;
    if (format == 1) {
        out.kind = ColrPaint::Kind::Layers;
        out.layer_count = r.c.u8();
        out.first_layer = r.c.u32();
    } else if (format <= 3) {
        out.kind = ColrPaint::Kind::Solid;
        out.palette_index = r.c.u16();
        out.alpha = r.c.f2dot14();
    } else if (format <= 9) {
        r.gradient(format, out);
    } else if (format == 10) {
        out.kind = ColrPaint::Kind::Glyph;
        r.child(out.child);
        out.glyph = r.c.u16();
    } else if (format == 11) {
        out.kind = ColrPaint::Kind::ColrGlyph;
        out.glyph = r.c.u16();
    } else if (format <= 31) {
        out.kind = ColrPaint::Kind::Transform;
        r.child(out.child);
        out.transform = r.transform(format);
    } else {
        out.kind = ColrPaint::Kind::Composite;
        r.child(out.child);
        out.mode = r.c.u8();
        r.child(out.backdrop);
    }
    return r.c.ok;
}

}  // namespace casteljau::text_detail
