// libFuzzer target: the C API (include/casteljau/casteljau.h) driven by random call sequences.
// The input is a program: each byte picks a call, the bytes after it its arguments, read as
// doubles from a table of awkward values (0, -0, NaN, +/-inf, 1e300, 1e-300, 32769, ...) or as raw
// 8-byte doubles, and handles from small pools of live objects (NULL when the pool is empty).
// Image sizes above 256 are kept only when they exceed the canvas limit (so the limit error is
// exercised without gigabyte allocations). One call sets the process-wide limits from random bytes
// and a random struct size; they are reset after each input. Every object is destroyed at the
// end, so the leak checker sees anything the API forgets.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/casteljau.h"

namespace {

class Reader {
public:
    Reader(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
    bool done() const { return i_ >= n_; }
    std::uint8_t byte() { return i_ < n_ ? d_[i_++] : 0; }
    double number() {
        static const double kTable[] = {0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 10.0, 100.0, 255.0, 32769.0, 1e6, -1e6,
                                        1e300, -1e300, 1e-300, std::numeric_limits<double>::quiet_NaN(),
                                        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                        3.7, 0.25, 64.0, -5.5, 1e15, 4e15};
        const std::uint8_t b = byte();
        if (b < 200) return kTable[b % (sizeof kTable / sizeof kTable[0])];
        double v = 0;
        std::uint8_t raw[8] = {};
        for (std::uint8_t& r : raw) r = byte();
        std::memcpy(&v, raw, 8);
        return v;
    }
    int small_int() { return static_cast<int>(byte()) - 16; }
    std::string text() {
        const std::size_t len = byte();
        std::string s;
        while (s.size() < len && !done()) s.push_back(static_cast<char>(byte()));
        return s;
    }

private:
    const std::uint8_t* d_;
    std::size_t n_, i_ = 0;
};

// An enum value from any int, as a C caller may pass it (casteljau.h gives the enumerations int as
// their underlying type in C++, so every int is a value of them).
template <class E>
E as_enum(int v) {
    return static_cast<E>(v);
}

template <class T>
T* pick(std::vector<T*>& pool, Reader& r) {
    if (pool.empty()) return nullptr;
    return pool[r.byte() % pool.size()];
}

casteljau_color color(Reader& r) {
    return {r.byte(), r.byte(), r.byte(), r.byte()};
}

casteljau_matrix matrix(Reader& r) { return {r.number(), r.number(), r.number(), r.number(), r.number(), r.number()}; }

int image_side(Reader& r) {
    const double v = r.number();
    if (!(v == v)) return 0;
    if (v > 32768) return 40000;  // past the limit: an error, no allocation
    if (v > 256) return 256;
    return static_cast<int>(std::max(-2.0, v));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Reader r(data, size);
    std::vector<casteljau_path*> paths;
    std::vector<casteljau_paint*> paints;
    std::vector<casteljau_image*> images;
    std::vector<casteljau_canvas*> canvases;
    std::vector<casteljau_stroke*> strokes;
    int steps = 0;
    while (!r.done() && ++steps < 400) {
        const std::uint8_t op = r.byte() % 33;
        casteljau_status s = CASTELJAU_OK;
        switch (op) {
            case 0: if (paths.size() < 8) paths.push_back(casteljau_path_create()); break;
            case 1: {
                casteljau_path* p = nullptr;
                s = casteljau_path_from_svg(r.text().c_str(), &p);
                if (p) paths.push_back(p);
                break;
            }
            case 2: s = casteljau_path_move_to(pick(paths, r), r.number(), r.number()); break;
            case 3: s = casteljau_path_line_to(pick(paths, r), r.number(), r.number()); break;
            case 4: s = casteljau_path_cubic_to(pick(paths, r), r.number(), r.number(), r.number(), r.number(), r.number(), r.number()); break;
            case 5: s = casteljau_path_add_ellipse(pick(paths, r), r.number(), r.number(), r.number(), r.number()); break;
            case 6: s = casteljau_path_close(pick(paths, r)); break;
            case 7: {
                const casteljau_matrix m = matrix(r);
                s = casteljau_path_transform(pick(paths, r), &m);
                break;
            }
            case 8: {
                casteljau_paint* p = nullptr;
                s = casteljau_paint_create_solid(color(r), &p);
                if (p) paints.push_back(p);
                break;
            }
            case 9: {
                casteljau_gradient_stop stops[3] = {{r.number(), color(r)}, {r.number(), color(r)}, {r.number(), color(r)}};
                casteljau_paint* p = nullptr;
                const casteljau_matrix m = matrix(r);
                const bool radial = r.byte() & 1;
                const auto spread = as_enum<casteljau_spread>(r.small_int());
                if (radial)
                    s = casteljau_paint_create_radial(r.number(), r.number(), r.number(), r.number(), r.number(), r.number(),
                                                      stops, r.byte() % 4, spread, (r.byte() & 1) ? &m : nullptr, &p);
                else
                    s = casteljau_paint_create_linear(r.number(), r.number(), r.number(), r.number(), stops, r.byte() % 4,
                                                      spread, (r.byte() & 1) ? &m : nullptr, &p);
                if (p) paints.push_back(p);
                break;
            }
            case 10: {
                casteljau_paint* p = nullptr;
                const casteljau_matrix m = matrix(r);
                s = casteljau_paint_create_image(pick(images, r), as_enum<casteljau_sampling>(r.small_int()), &m,
                                                 r.byte() & 1, &p);
                if (p) paints.push_back(p);
                break;
            }
            case 11: s = casteljau_paint_set_opacity(pick(paints, r), r.number()); break;
            case 12: s = casteljau_paint_set_blend_mode(pick(paints, r), as_enum<casteljau_blend_mode>(r.small_int())); break;
            case 13: {
                if (images.size() >= 4) break;
                casteljau_image* im = nullptr;
                s = casteljau_image_create(image_side(r), image_side(r), &im);
                if (im) images.push_back(im);
                break;
            }
            case 14: {
                casteljau_image* im = pick(images, r);
                if (!im || canvases.size() >= 4) break;
                casteljau_canvas* c = nullptr;
                s = casteljau_canvas_create(im, &c);
                if (c) canvases.push_back(c);
                break;
            }
            case 15: {
                if (strokes.size() < 4) strokes.push_back(casteljau_stroke_create());
                casteljau_stroke* st = pick(strokes, r);
                s = casteljau_stroke_set_width(st, r.number());
                casteljau_stroke_set_cap(st, as_enum<casteljau_line_cap>(r.small_int()));
                casteljau_stroke_set_join(st, as_enum<casteljau_line_join>(r.small_int()), r.number());
                const double d[3] = {r.number(), r.number(), r.number()};
                casteljau_stroke_set_dashes(st, d, r.byte() % 4, r.number());
                break;
            }
            case 16: s = casteljau_canvas_save(pick(canvases, r)); break;
            case 17: s = casteljau_canvas_restore(pick(canvases, r)); break;
            case 18: s = casteljau_canvas_translate(pick(canvases, r), r.number(), r.number()); break;
            case 19: s = casteljau_canvas_scale(pick(canvases, r), r.number(), r.number()); break;
            case 20: s = casteljau_canvas_rotate(pick(canvases, r), r.number()); break;
            case 21: {
                const casteljau_matrix m = matrix(r);
                s = casteljau_canvas_concat(pick(canvases, r), &m);
                break;
            }
            case 22: s = casteljau_canvas_clip_rect(pick(canvases, r), r.number(), r.number(), r.number(), r.number()); break;
            case 23: s = casteljau_canvas_clip_path(pick(canvases, r), pick(paths, r), as_enum<casteljau_fill_rule>(r.small_int())); break;
            case 24: s = casteljau_canvas_set_opacity(pick(canvases, r), r.number()); break;
            case 25: s = casteljau_canvas_set_blend_mode(pick(canvases, r), as_enum<casteljau_blend_mode>(r.small_int())); break;
            case 26: s = casteljau_canvas_clear(pick(canvases, r), color(r)); break;
            case 27: s = casteljau_canvas_fill_path(pick(canvases, r), pick(paths, r), pick(paints, r), as_enum<casteljau_fill_rule>(r.byte() % 3)); break;
            case 28: s = casteljau_canvas_stroke_path(pick(canvases, r), pick(paths, r), pick(strokes, r), pick(paints, r)); break;
            case 29: {
                const casteljau_matrix m = matrix(r);
                s = casteljau_canvas_draw_image(pick(canvases, r), pick(images, r), (r.byte() & 1) ? &m : nullptr,
                                                as_enum<casteljau_sampling>(r.small_int()), r.number());
                break;
            }
            case 30: s = casteljau_canvas_begin_layer(pick(canvases, r), r.number(), as_enum<casteljau_blend_mode>(r.small_int())); break;
            case 31: {
                s = casteljau_canvas_end_layer(pick(canvases, r));
                casteljau_image* im = pick(images, r);
                if (im && r.byte() == 7) {
                    casteljau_canvas* c = nullptr;
                    const int w = casteljau_image_width(im), h = casteljau_image_height(im);
                    s = casteljau_canvas_create_for_pixels(casteljau_image_data(im), w, h, casteljau_image_stride(im), &c);
                    casteljau_canvas_fill_rect(c, r.number(), r.number(), r.number(), r.number(), pick(paints, r));
                    casteljau_canvas_destroy(c);
                }
                break;
            }
            case 32: {
                // Random bytes over the limits in force, applied with a random size: refused
                // whole or applied whole, and every later call checks against them.
                casteljau_limits l;
                s = casteljau_limits_get(&l, sizeof l);
                auto* raw = reinterpret_cast<std::uint8_t*>(&l);
                for (int n = r.byte() % 8; n > 0; --n) raw[r.byte() % sizeof l] = r.byte();
                const std::size_t size = (r.byte() & 1) ? sizeof l : r.byte() % (sizeof l + 2);
                s = casteljau_limits_set(&l, size);
                break;
            }
        }
        // Every failure leaves a message.
        if (s != CASTELJAU_OK && casteljau_last_error()[0] == '\0') __builtin_trap();
    }
    // Canvases borrow images: destroy them first.
    for (casteljau_canvas* c : canvases) casteljau_canvas_destroy(c);
    for (casteljau_image* i : images) casteljau_image_destroy(i);
    for (casteljau_path* p : paths) casteljau_path_destroy(p);
    for (casteljau_paint* p : paints) casteljau_paint_destroy(p);
    for (casteljau_stroke* st : strokes) casteljau_stroke_destroy(st);
    casteljau_limits_reset();
    return 0;
}
