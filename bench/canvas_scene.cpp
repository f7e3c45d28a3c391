// bench/canvas_scene.cpp: a canvas scene of 10,000 mixed shapes at 1920 x 1080, drawn by casteljau's
// Canvas and by Cairo (image surface, ARGB32, default antialiasing) side by side in one process.
// The scene is five parts of 2,000 items each, timed separately: solid fills (rectangles, ellipses,
// stars), strokes (polylines and curves, round joins, some dashed), gradient fills (linear and
// radial), clipped fills (each item: save, clip to a circle, fill a rectangle, restore) and text
// (a short string in DejaVu Sans at 10 to 30 px). Items are generated from a fixed seed, so both
// libraries draw the same geometry. Reported: the median of the rounds' thread CPU time per part
// (bench/timer.hpp), casteljau on one thread as Cairo. `--quick`: 200 items per part and one round
// (the ctest smoke entry). `--only PART` times one part (fills, strokes, gradients, "clipped fills",
// text), to profile it.
// `--accuracy`: each part is also drawn by casteljau at 0.001 px (curves, strokes and glyph masks
// flattened that finely, exact overlaps: the exact reference of the other benchmarks), and both
// libraries' images at their defaults are compared with it: mean and max |difference| per
// channel, in 1/255, over the pixels any of the three images changed (Cairo's text is left out:
// it places glyphs by its own hinted metrics, so its picture is a different layout).
// Usage: canvas_scene [--quick] [--rounds N] [--accuracy] [--png PREFIX] (writes
// PREFIX-casteljau.png and PREFIX-cairo.png of the whole scene to compare by eye).
#include <cairo-ft.h>
#include <cairo.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/png.hpp"
#include "casteljau/text.hpp"
#include "casteljau/threads.hpp"
#include "timer.hpp"

using namespace casteljau;

namespace {

constexpr int kW = 1920, kH = 1080;

struct Item {
    int kind = 0;  // shape: 0 rect, 1 ellipse, 2 star / curve
    double x = 0, y = 0, w = 0, h = 0, angle = 0, width = 1;
    Color c0, c1;
    bool dashed = false, radial = false;
    std::string text;
    double size = 12;
};

enum Part { Fills, Strokes, Gradients, Clips, Text, kParts };
const char* kPartNames[kParts] = {"fills", "strokes", "gradients", "clipped fills", "text"};

std::vector<Item> make_items(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(0, kW), uy(0, kH), us(8, 120), ua(0, 6.283), uw(0.5, 8), usz(10, 30);
    auto col = [&] {
        return Color::rgba(static_cast<std::uint8_t>(rng() % 256), static_cast<std::uint8_t>(rng() % 256),
                           static_cast<std::uint8_t>(rng() % 256), static_cast<std::uint8_t>(128 + rng() % 128));
    };
    static const char* kWords[] = {"casteljau", "Bezier", "raster 42", "exact area", "Hello, world", "curves"};
    std::vector<Item> items(static_cast<std::size_t>(count));
    for (Item& it : items) {
        it.kind = static_cast<int>(rng() % 3);
        it.x = ux(rng);
        it.y = uy(rng);
        it.w = us(rng);
        it.h = us(rng);
        it.angle = ua(rng);
        it.width = uw(rng);
        it.c0 = col();
        it.c1 = col();
        it.dashed = rng() % 4 == 0;
        it.radial = rng() % 2 == 0;
        it.text = kWords[rng() % 6];
        it.size = usz(rng);
    }
    return items;
}

// The shape of an item as a Path (user space = pixels): rectangle, ellipse or 5-point star
// (fills), or an open zigzag of cubics (strokes).
Path shape(const Item& it, bool open) {
    Path p;
    if (open) {
        p.move_to(it.x, it.y);
        for (int k = 1; k <= 3; ++k)
            p.cubic_to({it.x + it.w * (k - 0.66), it.y - it.h * 0.5}, {it.x + it.w * (k - 0.33), it.y + it.h * 0.5},
                       {it.x + it.w * k * 0.9, it.y + (k % 2 ? 10 : -10)});
        return p;
    }
    switch (it.kind) {
        case 0: p.add_rect(Rect::from_xywh(it.x, it.y, it.w, it.h)); break;
        case 1: p.add_ellipse({it.x, it.y}, it.w / 2, it.h / 2); break;
        default:
            for (int k = 0; k < 10; ++k) {
                const double r = k % 2 ? it.w * 0.2 : it.w * 0.5, a = it.angle + k * 3.14159265358979 / 5;
                const Point q{it.x + r * std::cos(a), it.y + r * std::sin(a)};
                if (k == 0)
                    p.move_to(q);
                else
                    p.line_to(q);
            }
            p.close();
    }
    return p;
}

// --- casteljau ---------------------------------------------------------------------------------

void draw_casteljau(Canvas& c, Part part, const std::vector<Item>& items, const Font& font, GlyphCache& cache) {
    for (const Item& it : items) {
        switch (part) {
            case Fills: c.fill_path(shape(it, false), Paint::solid(it.c0)); break;
            case Strokes: {
                StrokeStyle st;
                st.width = it.width;
                st.join = LineJoin::Round;
                if (it.dashed) st.dashes = {12, 6};
                c.stroke_path(shape(it, true), st, Paint::solid(it.c0));
                break;
            }
            case Gradients: {
                std::vector<GradientStop> stops{{0, it.c0}, {1, it.c1}};
                Shader s = it.radial ? Shader::radial({it.x, it.y}, std::max(it.w, it.h) / 2, {it.x, it.y}, 0, stops)
                                     : Shader::linear({it.x - it.w / 2, it.y}, {it.x + it.w / 2, it.y}, stops);
                c.fill_path(shape(it, false), Paint::shaded(std::move(s)));
                break;
            }
            case Clips: {
                c.save();
                Path circle;
                circle.add_circle({it.x, it.y}, it.w / 2);
                c.clip_path(circle);
                c.fill_rect(Rect::from_xywh(it.x - it.w / 2, it.y - it.h / 2, it.w * 0.8, it.h), Paint::solid(it.c0));
                c.restore();
                break;
            }
            case Text: {
                TextStyle style;
                style.size = it.size;
                draw_text(c, layout_text(it.text, font, style), {it.x, it.y}, Paint::solid(it.c0), &cache);
                break;
            }
            default: break;
        }
    }
}

// --- Cairo -------------------------------------------------------------------------------------

void set_source(cairo_t* cr, Color c) { cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a / 255.0); }

struct ToCairo {
    cairo_t* cr;
    void move(Point p) { cairo_move_to(cr, p.x, p.y); }
    void line(Point, Point p) { cairo_line_to(cr, p.x, p.y); }
    void quad(Point p0, Point c, Point p) {
        const Point c1 = p0 + (c - p0) * (2.0 / 3.0), c2 = p + (c - p) * (2.0 / 3.0);
        cairo_curve_to(cr, c1.x, c1.y, c2.x, c2.y, p.x, p.y);
    }
    void cubic(Point, Point c1, Point c2, Point p) { cairo_curve_to(cr, c1.x, c1.y, c2.x, c2.y, p.x, p.y); }
    void conic(Point, Point, Point p, double) { cairo_line_to(cr, p.x, p.y); }
    void close(Point, Point) { cairo_close_path(cr); }
};

void cairo_path(cairo_t* cr, const Path& p) {
    cairo_new_path(cr);
    p.visit(ToCairo{cr});
}

void draw_cairo(cairo_t* cr, Part part, const std::vector<Item>& items) {
    for (const Item& it : items) {
        switch (part) {
            case Fills:
                cairo_path(cr, shape(it, false));
                set_source(cr, it.c0);
                cairo_fill(cr);
                break;
            case Strokes: {
                cairo_path(cr, shape(it, true));
                set_source(cr, it.c0);
                cairo_set_line_width(cr, it.width);
                cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
                const double d[2] = {12, 6};
                cairo_set_dash(cr, d, it.dashed ? 2 : 0, 0);
                cairo_stroke(cr);
                break;
            }
            case Gradients: {
                cairo_pattern_t* pat =
                    it.radial ? cairo_pattern_create_radial(it.x, it.y, 0, it.x, it.y, std::max(it.w, it.h) / 2)
                              : cairo_pattern_create_linear(it.x - it.w / 2, it.y, it.x + it.w / 2, it.y);
                for (const auto& [o, c] : {std::pair{0.0, it.c0}, std::pair{1.0, it.c1}})
                    cairo_pattern_add_color_stop_rgba(pat, o, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a / 255.0);
                cairo_path(cr, shape(it, false));
                cairo_set_source(cr, pat);
                cairo_fill(cr);
                cairo_pattern_destroy(pat);
                break;
            }
            case Clips:
                cairo_save(cr);
                cairo_new_path(cr);
                cairo_arc(cr, it.x, it.y, it.w / 2, 0, 6.283185307179586);
                cairo_clip(cr);
                cairo_rectangle(cr, it.x - it.w / 2, it.y - it.h / 2, it.w * 0.8, it.h);
                set_source(cr, it.c0);
                cairo_fill(cr);
                cairo_restore(cr);
                break;
            case Text:
                cairo_set_font_size(cr, it.size);
                set_source(cr, it.c0);
                cairo_move_to(cr, it.x, it.y + it.size * 0.76);  // casteljau places the box's top; Cairo the baseline
                cairo_show_text(cr, it.text.c_str());
                break;
            default: break;
        }
    }
}

// Cairo's ARGB32 pixel (premultiplied, native-endian 32-bit words) as premultiplied RGBA bytes.
void cairo_rgba(cairo_surface_t* surf, int x, int y, std::uint8_t out[4]) {
    const unsigned char* row = cairo_image_surface_get_data(surf) + y * cairo_image_surface_get_stride(surf);
    std::uint32_t v;
    std::memcpy(&v, row + 4 * x, 4);
    out[0] = static_cast<std::uint8_t>(v >> 16);
    out[1] = static_cast<std::uint8_t>(v >> 8);
    out[2] = static_cast<std::uint8_t>(v);
    out[3] = static_cast<std::uint8_t>(v >> 24);
}

struct Diff {
    double mean = 0;
    int max = 0;
};

// Differences from `ref` of `ours` and of Cairo's surface, over the pixels any of them changed
// from the white background.
void compare(const Pixmap& ref, const Pixmap& ours, cairo_surface_t* surf, Diff& d_ours, Diff& d_cairo) {
    cairo_surface_flush(surf);
    double sum_o = 0, sum_c = 0;
    long n = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const std::uint8_t* r = ref.row(y) + 4 * x;
            const std::uint8_t* o = ours.row(y) + 4 * x;
            std::uint8_t c[4];
            cairo_rgba(surf, x, y, c);
            bool touched = false;
            for (int k = 0; k < 4; ++k) touched |= r[k] != 255 || o[k] != 255 || c[k] != 255;
            if (!touched) continue;
            ++n;
            for (int k = 0; k < 4; ++k) {
                const int eo = std::abs(int{o[k]} - int{r[k]}), ec = std::abs(int{c[k]} - int{r[k]});
                sum_o += eo;
                sum_c += ec;
                d_ours.max = std::max(d_ours.max, eo);
                d_cairo.max = std::max(d_cairo.max, ec);
            }
        }
    d_ours.mean = n ? sum_o / (4.0 * static_cast<double>(n)) : 0;
    d_cairo.mean = n ? sum_c / (4.0 * static_cast<double>(n)) : 0;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    int per_part = 2000, rounds = 5;
    std::string png_prefix, only;
    bool accuracy = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) {
            per_part = 200;
            rounds = 1;
        } else if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc)
            rounds = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--accuracy"))
            accuracy = true;
        else if (!std::strcmp(argv[i], "--png") && i + 1 < argc)
            png_prefix = argv[++i];
        else if (!std::strcmp(argv[i], "--only") && i + 1 < argc)
            only = argv[++i];
        else {
            std::fprintf(stderr,
                         "usage: canvas_scene [--quick] [--rounds N] [--accuracy] [--png PREFIX] [--only PART]\n");
            return 2;
        }
    }
    // One thread, as Cairo draws: the glyph cache would otherwise rasterize masks on the pool's
    // threads, whose time the calling thread's clock does not see.
    set_thread_count(1);
    const Font font = Font::load(CASTELJAU_BENCH_FONT);
    FT_Library ft;
    FT_Face face;
    if (FT_Init_FreeType(&ft) || FT_New_Face(ft, CASTELJAU_BENCH_FONT, 0, &face)) {
        std::fprintf(stderr, "FreeType failed\n");
        return 1;
    }
    cairo_font_face_t* cface = cairo_ft_font_face_create_for_ft_face(face, 0);

    std::vector<std::vector<Item>> parts;
    for (int p = 0; p < kParts; ++p) parts.push_back(make_items(per_part, 1000u + static_cast<unsigned>(p)));

    Pixmap pm(kW, kH);
    cairo_surface_t* surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kW, kH);
    std::printf("canvas scene: %d items per part, %d x %d, median of %d rounds (thread CPU ms)\n", per_part, kW, kH,
                rounds);
    std::printf("%-14s %12s %12s %8s\n", "part", "casteljau", "Cairo", "ratio");
    double total_c = 0, total_k = 0;
    for (int p = 0; p < kParts; ++p) {
        if (!only.empty() && only != kPartNames[p]) continue;
        std::vector<double> tc, tk;
        for (int r = 0; r < rounds; ++r) {
            pm.fill(Color::white());
            GlyphCache cache;
            Canvas canvas(pm);
            double t0 = bench::thread_cpu_seconds();
            draw_casteljau(canvas, static_cast<Part>(p), parts[static_cast<std::size_t>(p)], font, cache);
            tc.push_back(bench::thread_cpu_seconds() - t0);

            cairo_t* cr = cairo_create(surf);
            cairo_set_source_rgb(cr, 1, 1, 1);
            cairo_paint(cr);
            cairo_set_font_face(cr, cface);
            t0 = bench::thread_cpu_seconds();
            draw_cairo(cr, static_cast<Part>(p), parts[static_cast<std::size_t>(p)]);
            cairo_surface_flush(surf);
            tk.push_back(bench::thread_cpu_seconds() - t0);
            cairo_destroy(cr);
        }
        const double mc = median(tc) * 1e3, mk = median(tk) * 1e3;
        total_c += mc;
        total_k += mk;
        std::printf("%-14s %12.1f %12.1f %8.2f\n", kPartNames[p], mc, mk, mc / mk);
    }
    std::printf("%-14s %12.1f %12.1f %8.2f\n", "all", total_c, total_k, total_c / total_k);
    if (accuracy) {
        std::printf("\nagainst casteljau at 0.001 px, mean / max |difference| per channel in 1/255\n");
        std::printf("%-14s %14s %14s\n", "part", "casteljau", "Cairo");
        Pixmap ref(kW, kH);
        for (int p = 0; p < kParts; ++p) {
            const auto& items = parts[static_cast<std::size_t>(p)];
            ref.fill(Color::white());
            {
                Canvas canvas(ref);
                canvas.fill_options().tolerance = 0.001;
                GlyphCache fine(64u << 20, 0.001);
                draw_casteljau(canvas, static_cast<Part>(p), items, font, fine);
            }
            pm.fill(Color::white());
            {
                Canvas canvas(pm);
                GlyphCache cache;
                draw_casteljau(canvas, static_cast<Part>(p), items, font, cache);
            }
            cairo_t* cr = cairo_create(surf);
            cairo_set_source_rgb(cr, 1, 1, 1);
            cairo_paint(cr);
            cairo_set_font_face(cr, cface);
            draw_cairo(cr, static_cast<Part>(p), items);
            cairo_destroy(cr);
            Diff dc, dk;
            compare(ref, pm, surf, dc, dk);
            if (p == Text)  // Cairo places glyphs by its own hinted metrics: not the same picture
                std::printf("%-14s %8.3f / %-3d %14s\n", kPartNames[p], dc.mean, dc.max, "(other layout)");
            else
                std::printf("%-14s %8.3f / %-3d %8.3f / %-3d\n", kPartNames[p], dc.mean, dc.max, dk.mean, dk.max);
        }
    }
    if (!png_prefix.empty()) {
        pm.fill(Color::white());
        Canvas canvas(pm);
        GlyphCache cache;
        cairo_t* cr = cairo_create(surf);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_paint(cr);
        cairo_set_font_face(cr, cface);
        for (int p = 0; p < kParts; ++p) {
            draw_casteljau(canvas, static_cast<Part>(p), parts[static_cast<std::size_t>(p)], font, cache);
            draw_cairo(cr, static_cast<Part>(p), parts[static_cast<std::size_t>(p)]);
        }
        cairo_destroy(cr);
        write_png(pm, png_prefix + "-casteljau.png");
        cairo_surface_write_to_png(surf, (png_prefix + "-cairo.png").c_str());
    }
    cairo_surface_destroy(surf);
    cairo_font_face_destroy(cface);
    FT_Done_Face(face);
    FT_Done_FreeType(ft);
    return 0;
}
