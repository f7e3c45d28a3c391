// bench/curve_stress: 2000 random self-intersecting cubic paths on a 1024 x 1024 canvas,
// casteljau against FreeType and AGG in one process, nonzero and even-odd.
//
// Usage: curve_stress [--paths 2000] [--rounds 5] [--seed 1] [--check N]
// Each path is one closed contour of four cubics whose end and control points are uniform in a
// random square of 64 to 512 px inside the canvas (so nearly every path crosses itself, often many
// times). Timed per round (thread CPU time, best of --rounds): every path filled into an 8-bit
// coverage buffer of its own box (the control bounds rounded out, cleared first), by
//   casteljau             Rasterizer::fill, default options (exact; no topology given)
//   casteljau (exact off) plain accumulation
//   FreeType              FT_Outline_Render (smooth, FT_RASTER_FLAG_AA), cubic outline in 26.6
//   AGG                   rasterizer_scanline_aa + conv_curve, gray8
// Accuracy against the exact reference: casteljau at a 0.001 px flattening tolerance with every
// shape through the per-cell overlap check (not the winding sweep), on the first --check paths
// (default 200): mean and max |difference| in 1/255, and the share of pixels off by more than
// 1/255.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <agg_conv_curve.h>
#include <agg_path_storage.h>
#include <agg_pixfmt_gray.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_u.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "casteljau/raster.hpp"
#include "timer.hpp"

namespace {

using casteljau::Point;

struct Shape {
    Point p[13];  // start, then 3 points per cubic; the last cubic ends at the start (p[12] unused)
    int x0, y0, w, h;
};

// Rows of 8-bit coverage of one shape's box.
using Render = std::function<const std::uint8_t*(const Shape&, bool even_odd)>;

class CasteljauRender {
public:
    CasteljauRender(bool exact, double tol, bool force_cells) {
        opts_.exact_overlaps = exact;
        opts_.tolerance = tol;
        if (force_cells) {
            opts_.topology = casteljau::Topology::Overlapping;
            opts_.winding_sweep = false;
        }
    }
    const std::uint8_t* operator()(const Shape& s, bool even_odd) {
        casteljau::Path p;
        p.move_to(s.p[0]);
        for (int k = 0; k < 4; ++k) p.cubic_to(s.p[1 + 3 * k], s.p[2 + 3 * k], k == 3 ? s.p[0] : s.p[3 + 3 * k]);
        p.close();
        opts_.rule = even_odd ? casteljau::FillRule::EvenOdd : casteljau::FillRule::NonZero;
        buf_.assign(static_cast<std::size_t>(s.w) * s.h, 0);
        sink_.buf = buf_.data();
        sink_.w = s.w;
        r_.fill(p, casteljau::Affine::translate(-s.x0, -s.y0), opts_, casteljau::IRect{0, 0, s.w, s.h}, sink_);
        return buf_.data();
    }

private:
    struct Sink final : casteljau::SpanSink {
        std::uint8_t* buf = nullptr;
        int w = 0;
        void row(int y, int x, int n, const std::uint8_t* c) override {
            std::memcpy(buf + static_cast<std::size_t>(y) * w + x, c, static_cast<std::size_t>(n));
        }
    };
    casteljau::FillOptions opts_;
    casteljau::Rasterizer r_;
    Sink sink_;
    std::vector<std::uint8_t> buf_;
};

class FreeTypeRender {
public:
    FreeTypeRender() { FT_Init_FreeType(&lib_); }
    ~FreeTypeRender() { FT_Done_FreeType(lib_); }
    const std::uint8_t* operator()(const Shape& s, bool even_odd) {
        // Points 0..11: the fourth cubic's end is the contour's start, where FreeType closes it.
        FT_Vector pts[12];
        char tags[12];
        for (int i = 0; i < 12; ++i) {
            // 26.6, y up, box corner at (0, 0).
            pts[i].x = std::lround((s.p[i].x - s.x0) * 64);
            pts[i].y = std::lround((s.y0 + s.h - s.p[i].y) * 64);
            tags[i] = (i % 3 == 0) ? FT_CURVE_TAG_ON : FT_CURVE_TAG_CUBIC;
        }
        short end = 11;
        FT_Outline o{};
        o.n_contours = 1;
        o.n_points = 12;
        o.points = pts;
        o.tags = tags;
        o.contours = &end;
        o.flags = even_odd ? FT_OUTLINE_EVEN_ODD_FILL : 0;
        buf_.assign(static_cast<std::size_t>(s.w) * s.h, 0);
        FT_Bitmap bm{};
        bm.rows = static_cast<unsigned>(s.h);
        bm.width = static_cast<unsigned>(s.w);
        bm.pitch = s.w;
        bm.buffer = buf_.data();
        bm.pixel_mode = FT_PIXEL_MODE_GRAY;
        bm.num_grays = 256;
        FT_Raster_Params params{};
        params.target = &bm;
        params.flags = FT_RASTER_FLAG_AA;
        FT_Outline_Render(lib_, &o, &params);
        return buf_.data();
    }

private:
    FT_Library lib_ = nullptr;
    std::vector<std::uint8_t> buf_;
};

// FreeType's bitmap has row 0 at the top with the outline's y up: the same rows as the others,
// since the outline above was flipped into the box.

class AggRender {
public:
    const std::uint8_t* operator()(const Shape& s, bool even_odd) {
        agg::path_storage ps;
        ps.move_to(s.p[0].x - s.x0, s.p[0].y - s.y0);
        for (int k = 0; k < 4; ++k) {
            const Point e = k == 3 ? s.p[0] : s.p[3 + 3 * k];
            ps.curve4(s.p[1 + 3 * k].x - s.x0, s.p[1 + 3 * k].y - s.y0, s.p[2 + 3 * k].x - s.x0,
                      s.p[2 + 3 * k].y - s.y0, e.x - s.x0, e.y - s.y0);
        }
        ps.close_polygon();
        buf_.assign(static_cast<std::size_t>(s.w) * s.h, 0);
        agg::rendering_buffer rbuf(buf_.data(), static_cast<unsigned>(s.w), static_cast<unsigned>(s.h), s.w);
        agg::pixfmt_gray8 pixf(rbuf);
        agg::renderer_base<agg::pixfmt_gray8> base(pixf);
        agg::renderer_scanline_aa_solid<agg::renderer_base<agg::pixfmt_gray8>> ren(base);
        ren.color(agg::gray8(255, 255));
        ras_.reset();
        ras_.filling_rule(even_odd ? agg::fill_even_odd : agg::fill_non_zero);
        agg::conv_curve<agg::path_storage> curve(ps);
        ras_.add_path(curve);
        agg::render_scanlines(ras_, sl_, ren);
        return buf_.data();
    }

private:
    std::vector<std::uint8_t> buf_;
    agg::rasterizer_scanline_aa<> ras_;
    agg::scanline_u8 sl_;
};

}  // namespace

int main(int argc, char** argv) {
    int npaths = 2000, rounds = 5, check = 200;
    unsigned seed = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--paths")
            npaths = std::max(1, std::atoi(argv[i + 1]));
        else if (a == "--rounds")
            rounds = std::max(1, std::atoi(argv[i + 1]));
        else if (a == "--seed")
            seed = static_cast<unsigned>(std::atoi(argv[i + 1]));
        else if (a == "--check")
            check = std::max(0, std::atoi(argv[i + 1]));
        else {
            std::fprintf(stderr, "usage: curve_stress [--paths N] [--rounds R] [--seed S] [--check N]\n");
            return 2;
        }
    }
    std::mt19937 rng(seed);
    std::vector<Shape> shapes(static_cast<std::size_t>(npaths));
    for (Shape& s : shapes) {
        const double side = std::uniform_real_distribution<double>(64, 512)(rng);
        const double ox = std::uniform_real_distribution<double>(0, 1024 - side)(rng);
        const double oy = std::uniform_real_distribution<double>(0, 1024 - side)(rng);
        std::uniform_real_distribution<double> u(0, side);
        double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
        for (Point& p : s.p) {
            p = {ox + u(rng), oy + u(rng)};
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        }
        s.x0 = static_cast<int>(std::floor(x0));
        s.y0 = static_cast<int>(std::floor(y0));
        s.w = static_cast<int>(std::ceil(x1)) - s.x0;
        s.h = static_cast<int>(std::ceil(y1)) - s.y0;
    }
    CasteljauRender cj(true, casteljau::kDefaultTolerance, false), cj_off(false, casteljau::kDefaultTolerance, false);
    CasteljauRender reference(true, 0.001, true);
    FreeTypeRender ft;
    AggRender agg;
    struct Entry {
        const char* name;
        Render f;
    };
    const Entry entries[] = {{"casteljau", std::ref(cj)},
                             {"casteljau (exact off)", std::ref(cj_off)},
                             {"FreeType", std::ref(ft)},
                             {"AGG", std::ref(agg)}};
    std::printf(
        "curve_stress: %d closed paths of 4 random cubics (squares of 64-512 px) on 1024 x 1024, seed %u, "
        "best of %d rounds (thread CPU time)\n\n",
        npaths, seed, rounds);
    std::printf("| rule | renderer | ms per 2000-path pass equivalent | paths/s | mean err | max err | > 1/255 |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|\n");
    for (bool eo : {false, true}) {
        for (const Entry& e : entries) {
            // Accuracy on the first `check` paths.
            double sum = 0;
            std::size_t pixels = 0, over = 0;
            int worst = 0;
            std::vector<std::uint8_t> ref;
            for (int i = 0; i < std::min(check, npaths); ++i) {
                const Shape& s = shapes[static_cast<std::size_t>(i)];
                const std::size_t n = static_cast<std::size_t>(s.w) * s.h;
                const std::uint8_t* r = reference(s, eo);
                ref.assign(r, r + n);
                const std::uint8_t* a = e.f(s, eo);
                for (std::size_t k = 0; k < n; ++k) {
                    const int d = std::abs(int(a[k]) - int(ref[k]));
                    sum += d;
                    over += d > 1;
                    worst = std::max(worst, d);
                }
                pixels += n;
            }
            double best = 1e30;
            for (int r = 0; r < rounds; ++r) {
                const double t0 = bench::thread_cpu_seconds();
                unsigned sink = 0;
                for (const Shape& s : shapes) sink += e.f(s, eo)[0];
                const double t = bench::thread_cpu_seconds() - t0;
                if (sink == 12345678u) std::printf(" ");
                best = std::min(best, t);
            }
            std::printf("| %s | %s | %.1f | %.0f | %.3f | %d | %.4f %% |\n", eo ? "even-odd" : "nonzero", e.name,
                        best * 1e3 * 2000.0 / npaths, npaths / best, pixels ? sum / pixels : 0.0, worst,
                        pixels ? 100.0 * over / pixels : 0.0);
        }
    }
    return 0;
}
