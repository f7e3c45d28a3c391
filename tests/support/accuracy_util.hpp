// tests/support/accuracy_util.hpp: shared steps of the accuracy, fill-rule and golden tests: render with
// the rasterizer under test, compute the independent reference, compare, and keep running totals
// for a final report. Test-only; uses Catch2 assertions.
#pragma once

#include <catch2/catch.hpp>

#include <string>

#include "casteljau/flatten.hpp"

#include "raster_check.hpp"
#include "reference_area.hpp"

namespace casteljau::testing {

// Polygons are exact: the acceptance bound is 1/255 per pixel; correct rounding of the exact area
// gives 0.5/255, which the rasterizer is also held to up to float noise (kRoundedErr).
inline constexpr double kPolygonMaxErr = 1.0;
inline constexpr double kRoundedErr = 0.51;
// Curves at the default tolerance against the finely flattened reference (the accuracy bound):
// max over every pixel, and mean over every pixel of the shape's pixel bounds (the compared
// rectangle is always the shape's bounds plus at most a few pixels, never an arbitrary canvas).
inline constexpr double kCurveMaxErr = 8.0;
inline constexpr double kCurveMeanErr = 0.5;

inline constexpr FillRule kRules[] = {FillRule::NonZero, FillRule::EvenOdd};

// Worst case seen over a series of comparisons, for a WARN line at the end of a test.
struct Worst {
    Comparison c;
    std::string label;
    std::size_t count = 0, misrounded = 0;
    double mean_max = 0, edge_mean_max = 0;  // the largest per-case means (all pixels, edge pixels)
    void add(const Comparison& x, const std::string& what) {
        ++count;
        misrounded += x.misrounded;
        mean_max = std::max(mean_max, x.mean_all);
        edge_mean_max = std::max(edge_mean_max, x.mean_err);
        if (count == 1 || x.max_err > c.max_err) {
            c = x;
            label = what;
        }
    }
    std::string text() const {
        return std::to_string(count) + " cases; largest per-case mean " + std::to_string(mean_max) +
               "/255 (over edge pixels only: " + std::to_string(edge_mean_max) +
               "/255); pixels not correctly rounded: " + std::to_string(misrounded) + "; worst case: " + label + ": " +
               c.text();
    }
};

// Renders the contours (given in user space, mapped by m) with `opts` inside `clip`, compares with
// the slab reference of the transformed contours, checks the sink contract, the polygon bound
// (REQUIRE) and correct rounding (CHECK).
// A reproducer for a failure message: the contours (full precision, when not too many points),
// the transform and the clip.
inline std::string describe(const ref::Contours& cs, const Affine& m, const IRect& clip) {
    std::size_t n = 0;
    for (const ref::Contour& c : cs) n += c.size();
    char buf[512];
    std::string s = "clip {" + std::to_string(clip.x0) + ", " + std::to_string(clip.y0) + ", " +
                    std::to_string(clip.x1) + ", " + std::to_string(clip.y1) + "}";
    std::snprintf(buf, sizeof buf, "; transform {%.17g, %.17g, %.17g, %.17g, %.17g, %.17g}; ", m.a, m.b, m.c, m.d, m.e,
                  m.f);
    s += buf;
    if (n > 64) return s + std::to_string(cs.size()) + " contours, " + std::to_string(n) + " points";
    s += "contours {";
    for (const ref::Contour& c : cs) {
        s += "{";
        for (Point p : c) {
            std::snprintf(buf, sizeof buf, "{%.17g, %.17g}, ", p.x, p.y);
            s += buf;
        }
        s += "}, ";
    }
    return s + "}";
}

inline Comparison check_one(const Rendered& out, const ref::CoverageGrid& truth, const ref::Contours& user,
                            const Affine& m, const FillOptions& opts, const IRect& clip, const std::string& what) {
    const Comparison c = compare(out, truth);
    INFO(what << (opts.rule == FillRule::NonZero ? " [nonzero]" : " [even-odd]")
              << (opts.exact_overlaps && !opts.winding_sweep ? " [overlap check]" : "") << ": " << c.text());
    INFO((c.max_err > kRoundedErr ? describe(user, m, clip) : std::string()));
    REQUIRE(out.contract_violation.empty());
    REQUIRE(out.nonzero_outside_window == 0);
    REQUIRE(c.max_err <= kPolygonMaxErr);
    CHECK(c.max_err <= kRoundedErr);
    return c;
}

// Renders the polygons with `opts` and checks them against the exact area. With exactness on and
// the winding sweep allowed, the shape is rendered and checked a second time through the per-cell
// overlap check (winding_sweep off), so both exact methods meet the same reference; r's
// last_stats() are then those of the overlap check. Returns the first render's comparison.
inline Comparison check_polygons(Rasterizer& r, const ref::Contours& user, const Affine& m, const FillOptions& opts,
                                 const IRect& clip, const std::string& what) {
    const Path path = ref::to_path(user);
    const ref::CoverageGrid truth = ref::slab_area(ref::transformed(user, m), opts.rule, clip);
    const Comparison c = check_one(render(r, path, m, opts, clip), truth, user, m, opts, clip, what);
    if (opts.exact_overlaps && opts.winding_sweep) {
        FillOptions cells = opts;
        cells.winding_sweep = false;
        check_one(render(r, path, m, cells, clip), truth, user, m, cells, clip, what);
    }
    return c;
}

inline Comparison check_polygons(Rasterizer& r, const ref::Contours& pixel_space, FillRule rule, const IRect& clip,
                                 const std::string& what) {
    FillOptions o;
    o.rule = rule;
    return check_polygons(r, pixel_space, Affine::identity(), o, clip, what);
}

// The polygon the library's own flattener makes of `path` at `tolerance` for a fill
// (casteljau::flatten with FlattenMode::AreaBalanced, as Rasterizer::fill does), as contours. The rasterizer must be exact on it (polygon bound): this separates scan-conversion
// errors from flattening error, which the curve bounds against the fine reference measure.
inline ref::Contours library_flattening(const Path& path, const Affine& m, double tolerance) {
    Polyline pl;
    flatten(path, m, tolerance, pl, FlattenMode::AreaBalanced);
    ref::Contours cs;
    std::size_t b = 0;
    for (std::uint32_t e : pl.contour_ends) {
        cs.emplace_back(pl.points.begin() + static_cast<std::ptrdiff_t>(b),
                        pl.points.begin() + static_cast<std::ptrdiff_t>(e));
        b = e;
    }
    return cs;
}

// Curved path at `opts.tolerance`: (1) exact on the library's own flattening (polygon bound),
// (2) against the finely flattened reference within the curve bounds (max, mean over the clip).
inline Comparison check_curves(Rasterizer& r, const Path& path, const Affine& m, const FillOptions& opts,
                               const IRect& clip, const std::string& what) {
    const Rendered out = render(r, path, m, opts, clip);
    const char* rule = opts.rule == FillRule::NonZero ? " [nonzero]" : " [even-odd]";
    REQUIRE(out.contract_violation.empty());
    REQUIRE(out.nonzero_outside_window == 0);
    const Comparison own = compare(out, ref::slab_area(library_flattening(path, m, opts.tolerance), opts.rule, clip));
    const ref::CoverageGrid truth = ref::path_reference(path, m, opts.rule, clip);
    const Comparison c = compare(out, truth);
    {
        INFO(what << rule << " against its own flattening (exact area): " << own.text());
        CHECK(own.max_err <= kPolygonMaxErr);
    }
    INFO(what << rule << ": " << c.text());
    CHECK(c.max_err <= kCurveMaxErr);
    CHECK(c.mean_all <= kCurveMeanErr);
    return c;
}

}  // namespace casteljau::testing
