// Regression tests for rasterizer bugs, each named after what broke.
#include <catch2/catch.hpp>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/raster.hpp"

using namespace casteljau;

namespace {
int ft_move(const FT_Vector* t, void* u) {
    static_cast<Path*>(u)->move_to(t->x, t->y);
    return 0;
}
int ft_line(const FT_Vector* t, void* u) {
    static_cast<Path*>(u)->line_to(t->x, t->y);
    return 0;
}
int ft_conic(const FT_Vector* c, const FT_Vector* t, void* u) {
    static_cast<Path*>(u)->quad_to({double(c->x), double(c->y)}, {double(t->x), double(t->y)});
    return 0;
}
int ft_cubic(const FT_Vector* c, const FT_Vector* d, const FT_Vector* t, void* u) {
    static_cast<Path*>(u)->cubic_to({double(c->x), double(c->y)}, {double(d->x), double(d->y)},
                                    {double(t->x), double(t->y)});
    return 0;
}
}  // namespace

// A cell accepted with three pieces keeps two edge ids in its tag; when a fourth edge later marks
// it, the dropped piece must be logged too, or the exact recomputation ignores it (DejaVu Sans '#'
// at 9 px: 232 instead of 202). For outlines whose winding keeps one sign, exact coverage can only be
// at most the accumulated one: integral of min(|w|, 1) <= min(|integral of w|, 1).
TEST_CASE("regression: marked cells with three accepted pieces log the dropped piece", "[raster][regression]") {
    FT_Library lib;
    REQUIRE(FT_Init_FreeType(&lib) == 0);
    FT_Face face;
    REQUIRE(FT_New_Face(lib, CASTELJAU_SOURCE_DIR "/fonts/DejaVuSans.ttf", 0, &face) == 0);
    Rasterizer r;
    FillOptions exact, plain;
    exact.tolerance = plain.tolerance = 0.005;
    plain.exact_overlaps = false;
    int bad = 0;
    std::string first;
    for (unsigned c = 0x21; c <= 0x7e; ++c) {
        REQUIRE(FT_Load_Char(face, c, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0);
        Path p;
        FT_Outline_Funcs f{ft_move, ft_line, ft_conic, ft_cubic, 0, 0};
        FT_Outline_Decompose(&face->glyph->outline, &f, &p);
        if (p.empty()) continue;
        for (double size : {9.0, 12.0}) {
            for (int k = 0; k < 4; ++k) {
                const double s = size / face->units_per_EM;
                const Affine m{s, 0, 0, -s, 10 + 0.25 * k, 300.75};
                const Mask a = r.fill_mask(p, m, exact), b = r.fill_mask(p, m, plain);
                for (int y = a.bounds.y0; y < a.bounds.y1; ++y)
                    for (int x = a.bounds.x0; x < a.bounds.x1; ++x)
                        if (a.at(x, y) > b.at(x, y) + 1 && bad++ == 0)
                            first = "U+" + std::to_string(c) + " size " + std::to_string(size) + " pixel " +
                                    std::to_string(x) + "," + std::to_string(y);
            }
        }
    }
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
    INFO("first: " << first);
    CHECK(bad == 0);
}

// A pixel crossed by thousands of mutually crossing segments made the exact slab decomposition
// take minutes (its work grows with slabs x pieces). Past a work budget the cell is integrated on
// 1024 horizontal lines instead; the result stays within a fraction of 1/255 of the truth,
// estimated here by point sampling of the winding number.
TEST_CASE("regression: thousands of crossings in one pixel finish and stay accurate", "[raster][regression]") {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> u(0.02, 0.98);
    std::vector<Point> pts;
    for (int i = 0; i < 3000; ++i) pts.push_back({3 + u(rng), 2 + u(rng)});
    Path p;
    p.add_polygon(pts);
    for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
        Rasterizer r;
        FillOptions o;
        o.rule = rule;
        const Mask m = r.fill_mask(p, Affine{}, o, IRect{0, 0, 8, 6});
        CHECK(r.last_stats().exact_cells >= 1);
        // Point-sampled truth on a 200 x 200 grid of the pixel (3, 2).
        int inside = 0;
        const int N = 200;
        for (int j = 0; j < N; ++j) {
            for (int i = 0; i < N; ++i) {
                const double x = 3 + (i + 0.5) / N, y = 2 + (j + 0.5) / N;
                int w = 0;
                for (std::size_t k = 0; k < pts.size(); ++k) {
                    const Point a = pts[k], b = pts[(k + 1) % pts.size()];
                    if ((a.y <= y) != (b.y <= y)) {
                        const double xc = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                        if (xc < x) w += b.y > a.y ? 1 : -1;
                    }
                }
                inside += rule == FillRule::NonZero ? (w != 0) : (w & 1);
            }
        }
        const double truth = 255.0 * inside / (N * N);
        INFO("rule " << (rule == FillRule::NonZero ? "nonzero" : "evenodd") << ": got " << int(m.at(3, 2))
                     << ", sampled " << truth);
        CHECK(std::abs(m.at(3, 2) - truth) <= 3.0);  // sampling noise of 40,000 points is ~1/255
        CHECK(m.at(0, 0) == 0);
    }
}

TEST_CASE("regression: a quadratic from DBL_MAX overflowing to NaN is refused, not walked", "[raster][regression]") {
    // Found by fuzz_raster: a control point at the smallest denormal between two end points at
    // DBL_MAX passed the finiteness check, and the flattener's differences overflowed to
    // infinity and NaN, which the cell walk then turned into out-of-range indices.
    const double big = 1.7976931348623157e308;
    Path p;
    p.move_to(big, 3.984375).quad_to({4.9406564584124654e-324, 0}, {big, 3.984375});
    Rasterizer r;
    FillOptions o;
    o.rule = FillRule::EvenOdd;
    o.exact_overlaps = false;
    try {
        (void)r.fill_mask(p, Affine{}, o, IRect{73, -20, 324, 147});
        FAIL("expected an error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Limit);
        CHECK(std::string(e.what()).find("coordinate") != std::string::npos);
    }
    // The limit itself: 1e15 px after the transform is drawn, beyond it is an error.
    Path edge;
    edge.move_to(0, 0).line_to(limits::kMaxCoordinate, 0).line_to(0, 10).close();
    CHECK_NOTHROW(r.fill_mask(edge, Affine{}, FillOptions{}, IRect{0, 0, 16, 16}));
    CHECK_THROWS_AS(r.fill_mask(edge, Affine::scale(2, 1), FillOptions{}, IRect{0, 0, 16, 16}), Error);
    // A shape wholly outside the target is skipped whatever its coordinates (text pushed far away
    // by a huge letter-spacing, say).
    Path far;
    far.move_to(1e300, 0).line_to(2e300, 0).line_to(1e300, 10).close();
    const Mask none = r.fill_mask(far, Affine{}, FillOptions{}, IRect{0, 0, 16, 16});
    CHECK(std::all_of(none.data.begin(), none.data.end(), [](std::uint8_t c) { return c == 0; }));
}

TEST_CASE("regression: a conic whose flattening overflows to NaN is refused, not walked", "[raster][regression]") {
    // Found by fuzz_raster: finite control points and a finite weight (DBL_MAX) passed every
    // check, but the conic's flattened points came out NaN and the cell walk indexed out of range.
    Path p;
    p.move_to(0, 0).conic_to({100, 100}, {10, 10}, 1.7976931348623157e308).close();
    Rasterizer r;
    try {
        (void)r.fill_mask(p, Affine{}, FillOptions{}, IRect{0, 0, 128, 128});
        FAIL("expected an error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::InvalidData); }
}
