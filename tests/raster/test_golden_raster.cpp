// Golden images of the rasterizer (golden/raster/*.png).
//
// What the images are: 8-bit coverage masks, not composited pictures (the Canvas and compositing
// have their own goldens): each pixel is opaque grey with r = g = b = coverage (white = covered),
// so a PNG round trip is exact. Curved scenes are flattened at an explicit 0.02 px, not the
// default tolerance, so the goldens do not churn when the default is retuned (the default itself is
// held to the acceptance bounds in test_raster_accuracy.cpp).
//
// Every scene is first validated against the independent exact-area reference in the same test:
// polygons within 1/255 per pixel; curves within max 8/255 and mean 0.5/255 of the finely
// flattened curve AND within 1/255 of the exact area of the polygon casteljau::flatten makes of
// them (so that a scan-conversion error cannot hide inside the curve bounds). Only then may CASTELJAU_UPDATE_GOLDEN=1 write the golden; the comparison with
// the golden allows max 2/255 and mean 0.05/255 (float summation order may differ between the
// SIMD targets Highway dispatches to).
#include <catch2/catch.hpp>

#include <cmath>

#include "accuracy_util.hpp"
#include "glyph_outline.hpp"
#include "golden.hpp"

using namespace casteljau;
using namespace casteljau::testing;
using ref::Contour;
using ref::Contours;

namespace {

constexpr double kGoldenTolerance = 0.02;  // flattening tolerance of the curved scenes, px
const golden::Tolerance kCompare{2, 0.05};

FillOptions options(FillRule rule) {
    FillOptions o;
    o.rule = rule;
    o.tolerance = kGoldenTolerance;
    return o;
}

// Renders, validates against `truth` (and, for curves, against the exact area of the library's own
// flattening), then compares with (or writes) the golden.
void scene(const std::string& name, const Path& path, const FillOptions& opts, const IRect& clip,
           const ref::CoverageGrid& truth, bool polygon) {
    Rasterizer r;
    const Rendered out = render(r, path, Affine::identity(), opts, clip);
    REQUIRE(out.contract_violation.empty());
    const Comparison c = compare(out, truth);
    bool passed = polygon ? c.max_err <= kPolygonMaxErr : (c.max_err <= kCurveMaxErr && c.mean_all <= kCurveMeanErr);
    std::string summary =
        std::string(polygon ? "polygon vs exact reference: " : "curves vs fine reference: ") + c.text();
    if (!polygon) {
        const Comparison own =
            compare(out, ref::slab_area(library_flattening(path, Affine::identity(), opts.tolerance), opts.rule, clip));
        passed = passed && own.max_err <= kPolygonMaxErr;
        summary += "; vs exact area of its own flattening: " + own.text();
    }
    INFO(name << ": " << summary);
    CHECK(passed);
    golden::check_golden(name, coverage_pixmap(out), kCompare, {passed, summary});
}

void polygon_scene(const std::string& name, const Contours& cs, FillRule rule, const IRect& clip) {
    scene(name, ref::to_path(cs), options(rule), clip, ref::slab_area(cs, rule, clip), true);
}

void curve_scene(const std::string& name, const Path& p, FillRule rule, const IRect& clip) {
    scene(name, p, options(rule), clip, ref::path_reference(p, Affine::identity(), rule, clip), false);
}

Contours stars() {
    return {star_polygon({32, 32}, 29, 5, 2), star_polygon({96.3, 32.4}, 29, 7, 3, 0.2),
            reversed(star_polygon({160.6, 31.7}, 29, 7, 2, 0.45)), star_polygon({224.25, 32.25}, 29, 9, 4, 0.1)};
}

Contours nested() {
    Contours cs;
    // Squares nested three deep, all clockwise (winding 1..3) and alternating (1, 0, 1).
    for (int k = 0; k < 3; ++k) {
        const double in = 3.5 + 8.25 * k;
        cs.push_back({{in, in}, {60.5 - in, in}, {60.5 - in, 60.5 - in}, {in, 60.5 - in}});
        Contour alt{{64 + in, in}, {124.5 - in, in}, {124.5 - in, 60.5 - in}, {64 + in, 60.5 - in}};
        cs.push_back(k % 2 ? reversed(alt) : alt);
    }
    // Three overlapping triangles: winding up to 3.
    for (int k = 0; k < 3; ++k) {
        const double a = 2 * kPi * k / 3 + 0.3;
        cs.push_back(regular_polygon({160 + 7 * std::cos(a), 32 + 7 * std::sin(a)}, 24, 3, true, a));
    }
    return cs;
}

Path circles() {
    Path p;
    p.add_circle({40, 40}, 30).add_circle({78.5, 42.25}, 28);
    p.append(Path().add_circle({60, 62}, 26.5).reversed());
    p.add_circle({60, 40}, 6);
    return p;
}

Path picture() {
    Path p;
    // A rounded rectangle with a round hole (opposite orientation).
    p.add_round_rect({4.5, 4.5, 60.5, 52.5}, 12, 9);
    p.append(Path().add_circle({32.5, 28.5}, 11.25).reversed());
    // A heart of cubics.
    p.move_to(100, 52).cubic_to({70, 30}, {80, 4}, {100, 18}).cubic_to({120, 4}, {130, 30}, {100, 52}).close();
    // A band bounded by quadratic waves.
    p.move_to(136, 20);
    for (int i = 0; i < 4; ++i) p.quad_to({143.0 + 14 * i, 6.0 + 28 * (i % 2)}, {150.0 + 14 * i, 20});
    p.line_to(192, 34);
    for (int i = 3; i >= 0; --i) p.quad_to({143.0 + 14 * i, 48.0 - 28 * (i % 2)}, {136.0 + 14 * i, 34});
    p.close();
    // A cubic with a loop, and a conic (elliptic) arc closed by its chord.
    p.move_to(200, 54).cubic_to({262, 2}, {196, 2}, {250, 54}).close();
    p.move_to(204, 8).conic_to({228, 8}, {228, 30}, 0.70710678118654752).close();
    return p;
}

}  // namespace

TEST_CASE("golden: self-intersecting stars, nonzero and even-odd", "[golden]") {
    polygon_scene("raster/star_nonzero", stars(), FillRule::NonZero, {0, 0, 256, 64});
    polygon_scene("raster/star_evenodd", stars(), FillRule::EvenOdd, {0, 0, 256, 64});
}

TEST_CASE("golden: nested contours and winding up to 3, nonzero and even-odd", "[golden]") {
    polygon_scene("raster/nested_nonzero", nested(), FillRule::NonZero, {0, 0, 192, 64});
    polygon_scene("raster/nested_evenodd", nested(), FillRule::EvenOdd, {0, 0, 192, 64});
}

TEST_CASE("golden: overlapping circles, nonzero and even-odd", "[golden]") {
    curve_scene("raster/circles_nonzero", circles(), FillRule::NonZero, {0, 0, 112, 96});
    curve_scene("raster/circles_evenodd", circles(), FillRule::EvenOdd, {0, 0, 112, 96});
}

TEST_CASE("golden: a line of DejaVu Sans glyphs", "[golden]") {
    GlyphFont font(dejavu_sans_path());
    const Path p = font.text(U"Casteljau & Bézier: ßgjQ@%0123", 28, {2.25, 30.5});
    curve_scene("raster/glyphs", p, FillRule::NonZero, {0, 0, 480, 40});
}

TEST_CASE("golden: a path picture of lines, quadratics, cubics and a conic", "[golden]") {
    curve_scene("raster/path_picture", picture(), FillRule::NonZero, {0, 0, 256, 64});
}
