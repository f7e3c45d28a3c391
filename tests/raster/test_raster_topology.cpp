// Topology decided before rasterizing (classify_topology, src/raster/topology.cpp): verdicts on
// shapes whose winding values are known by construction, and the contract that makes the fast path
// safe: every shape classified Simple renders with plain accumulation within the exact path's
// bound of the exact-area reference.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/font.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/text.hpp"
#include "glyph_outline.hpp"
#include "raster_check.hpp"
#include "reference_area.hpp"

using namespace casteljau;
using casteljau::testing::compare;
using casteljau::testing::join;
using casteljau::testing::polygon;
using casteljau::testing::render;
using casteljau::testing::square;

namespace {

// A ring over 250 px (two circles, 12 verbs): large for its number of segments, and simple.
Path ring() {
    Path rings;
    rings.add_circle({150, 150}, 120.3);
    rings.append(Path().add_circle({150, 150}, 60.7).reversed());
    return rings;
}

// The largest |difference| of two renders over the 300 x 300 target.
template <class R>
int max_difference(const R& a, const R& b) {
    int worst = 0;
    for (int y = 0; y < 300; ++y)
        for (int x = 0; x < 300; ++x) worst = std::max(worst, std::abs(a.at(x, y) - b.at(x, y)));
    return worst;
}

}  // namespace

TEST_CASE("topology: simple shapes are Simple", "[raster][topology]") {
    CHECK(classify_topology(square(0, 0, 10)) == Topology::Simple);
    CHECK(classify_topology(square(0, 0, 10, false)) == Topology::Simple);
    Path circle;
    circle.add_circle({50, 50}, 30);
    CHECK(classify_topology(circle) == Topology::Simple);
    // A ring: outer clockwise, hole counter-clockwise (windings 0, 1, 0).
    Path ring;
    ring.add_circle({50, 50}, 30);
    ring.append(Path().add_circle({50, 50}, 10).reversed());
    CHECK(classify_topology(ring) == Topology::Simple);
    // An island in a hole of the same direction as the outer contour (windings 0, 1, 0, 1).
    Path island = join(join(square(0, 0, 100), square(20, 20, 60, false)), square(40, 40, 20));
    CHECK(classify_topology(island) == Topology::Simple);
    // Two apart shapes of opposite directions (windings 0, 1 and 0, -1 do not meet).
    // Their values are 0, 1 and -1: not one unit interval, so not Simple.
    CHECK(classify_topology(join(square(0, 0, 10), square(20, 0, 10, false))) == Topology::Overlapping);
    // Open contour (closed implicitly by the rasterizer), quadratic and conic segments.
    Path open;
    open.move_to(0, 0).quad_to({10, -10}, {20, 0}).conic_to({20, 20}, {0, 20}, 0.7);
    CHECK(classify_topology(open) == Topology::Simple);
    // A sharp corner between two curves (their hulls leave the corner in directions 90 degrees apart).
    Path corner;
    corner.move_to(0, 0).quad_to({10, 0}, {20, 10}).quad_to({10, 10}, {0, 20}).close();
    CHECK(classify_topology(corner) == Topology::Simple);
    CHECK(classify_topology(Path()) == Topology::Simple);
}

TEST_CASE("topology: crossings, nesting and stacked copies are Overlapping", "[raster][topology]") {
    // Nested contours of one direction: winding 2 inside.
    CHECK(classify_topology(join(square(0, 0, 100), square(20, 20, 20))) == Topology::Overlapping);
    // Two overlapping squares.
    CHECK(classify_topology(join(square(0, 0, 10), square(5, 5, 10))) == Topology::Overlapping);
    // A stacked copy.
    CHECK(classify_topology(join(square(0, 0, 10), square(0, 0, 10))) == Topology::Overlapping);
    // A figure eight (self-crossing).
    CHECK(classify_topology(polygon({{0, 0}, {10, 10}, {10, 0}, {0, 10}})) == Topology::Overlapping);
    // A self-crossing cubic loop.
    Path loop;
    loop.move_to(0, 0).cubic_to({30, 30}, {-20, 30}, {10, 0}).close();
    CHECK(classify_topology(loop) == Topology::Overlapping);
    // Contours that cross where they share a vertex (windings 1 and -1 on either side of it).
    CHECK(classify_topology(polygon({{0, 0}, {10, 10}, {20, 20}, {20, 0}, {10, 10}, {0, 20}})) ==
          Topology::Overlapping);
    // Squares touching at a corner with opposite orientations (windings 1 and -1).
    CHECK(classify_topology(join(square(0, 0, 10), square(10, 10, 10, false))) == Topology::Overlapping);
    // A corner touching the middle of another square's side (not a shared vertex) is not proven.
    CHECK(classify_topology(join(square(0, 0, 10), square(10, 5, 10))) == Topology::Overlapping);
    // Consecutive curves whose hulls leave their shared point in overlapping directions: b starts
    // below a and ends above it, so it crosses a (windings 1 and -1).
    Path crossing_curves;
    crossing_curves.move_to(0, 0).quad_to({10, 10}, {20, 0}).quad_to({10, -2}, {0, 4}).close();
    CHECK(classify_topology(crossing_curves) == Topology::Overlapping);
    // A fold that does not return to the vertex it left (only part of the way back).
    CHECK(classify_topology(polygon({{0, 0}, {10, 0}, {20, 0}, {15, 0}, {10, 10}})) == Topology::Overlapping);
    // Non-finite coordinates never claim simplicity.
    CHECK(classify_topology(polygon({{0, 0}, {NAN, 0}, {5, 5}})) == Topology::Overlapping);
}

TEST_CASE("topology: contours touching at shared vertices without crossing are Simple", "[raster][topology]") {
    // Squares touching at a corner (map rings meeting at a node): windings 0 and 1.
    const Path corners = join(square(0, 0, 10), square(10, 10, 10));
    CHECK(classify_topology(corners) == Topology::Simple);
    // The same with three more squares around the corner... two of them touch it diagonally
    // opposite, so four squares meet at (10, 10) like a checkerboard.
    const Path checker = join(join(corners, square(10, 0, 10, false)), square(0, 10, 10, false));
    CHECK(classify_topology(checker) == Topology::Overlapping);  // the other two have the other orientation
    // A ring touching itself: a lake pinched onto the shore at (20, 0), traced in the opposite
    // direction (winding 0 inside it).
    const Path pinched_lake = polygon({{0, 0}, {20, 0}, {15, 10}, {25, 10}, {20, 0}, {40, 0}, {40, 40}, {0, 40}});
    CHECK(classify_topology(pinched_lake) == Topology::Simple);
    // The same lobe traced the other way crosses the shore at (20, 0) (winding 2 inside).
    const Path pinched_lobe = polygon({{0, 0}, {20, 0}, {25, 10}, {15, 10}, {20, 0}, {40, 0}, {40, 40}, {0, 40}});
    CHECK(classify_topology(pinched_lobe) == Topology::Overlapping);
    // Two triangles joined at one vertex, one contour (a bow tie pinched, not crossed).
    const Path bow = polygon({{0, 0}, {10, 10}, {20, 0}, {20, 20}, {10, 10}, {0, 20}});
    CHECK(classify_topology(bow) == Topology::Simple);
    // Spikes (straight out and back to the same vertex) add no area: the rest decides.
    CHECK(classify_topology(polygon({{0, 0}, {10, 0}, {20, 0}, {10, 0}, {10, 10}})) == Topology::Simple);
    CHECK(classify_topology(polygon({{0, 0}, {10, 0}, {10, 10}, {30, 30}, {10, 10}, {0, 10}})) == Topology::Simple);
    // A spike across the contour's start, and a contour that is only a spike.
    CHECK(classify_topology(polygon({{-5, -5}, {0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}})) == Topology::Simple);
    CHECK(classify_topology(polygon({{0, 0}, {10, 0}})) == Topology::Simple);
    // Curves touching at a vertex are not proven (only lines are).
    Path curved = square(0, 0, 10);
    curved.move_to(10, 10).quad_to({20, 10}, {20, 20}).line_to(10, 20).close();
    CHECK(classify_topology(curved) == Topology::Overlapping);
    // Every Simple one renders with plain accumulation as the exact reference does, with the shared
    // vertices inside pixels (not on their corners).
    Rasterizer r;
    FillOptions plain;
    plain.exact_overlaps = false;
    const Affine m = Affine::translate(0.37, 0.61) * Affine::scale(0.43, 0.41);
    const ref::Contours shapes[] = {
        {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{10, 10}, {20, 10}, {20, 20}, {10, 20}}},
        {{{0, 0}, {20, 0}, {15, 10}, {25, 10}, {20, 0}, {40, 0}, {40, 40}, {0, 40}}},
        {{{0, 0}, {10, 10}, {20, 0}, {20, 20}, {10, 10}, {0, 20}}},
        {{{0, 0}, {10, 0}, {10, 10}, {30, 30}, {10, 10}, {0, 10}}},
    };
    for (const ref::Contours& cs : shapes) {
        const Path p = ref::to_path(cs);
        REQUIRE(classify_topology(p) == Topology::Simple);
        for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            plain.rule = rule;
            const IRect clip{0, 0, 20, 20};
            const auto cmp = compare(render(r, p, m, plain, clip), ref::slab_area(ref::transformed(cs, m), rule, clip));
            INFO(cmp.text());
            CHECK(cmp.max_err <= 1.0);
        }
    }
}

TEST_CASE("topology: random polygons on a coarse lattice classified Simple render plainly within the exact bound",
          "[raster][topology]") {
    // Vertices on a 5 x 5 lattice: contours touch at shared vertices, run back along their own
    // edges, cross at vertices and along edges. Whatever is classified Simple must accumulate
    // exactly, under both rules, with the lattice points inside pixels.
    std::mt19937 rng(2026);
    std::uniform_int_distribution<int> coord(0, 4);
    Rasterizer r;
    FillOptions plain;
    plain.exact_overlaps = false;
    const Affine m = Affine::translate(0.3, 0.45) * Affine::scale(3.1, 2.9);
    const IRect clip{0, 0, 16, 16};
    int simple = 0, overlapping = 0, touching_simple = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        ref::Contours cs(1 + trial % 3);
        bool shares = false;
        std::vector<Point> seen;
        for (ref::Contour& c : cs) {
            const int n = 3 + static_cast<int>(rng() % 5);
            for (int k = 0; k < n; ++k) {
                const Point q{double(coord(rng)), double(coord(rng))};
                if (std::find(seen.begin(), seen.end(), q) != seen.end()) shares = true;
                seen.push_back(q);
                c.push_back(q);
            }
        }
        const Path p = ref::to_path(cs);
        if (classify_topology(p) != Topology::Simple) {
            ++overlapping;
            continue;
        }
        ++simple;
        if (shares) ++touching_simple;
        for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            plain.rule = rule;
            const auto cmp = compare(render(r, p, m, plain, clip), ref::slab_area(ref::transformed(cs, m), rule, clip));
            INFO("trial " << trial << ": " << cmp.text());
            CHECK(cmp.max_err <= 1.0);
        }
    }
    CHECK(simple > 200);
    CHECK(overlapping > 200);
    CHECK(touching_simple > 50);  // shapes proven through a shared vertex or a spike
}

TEST_CASE("topology: verdicts do not change under affine maps", "[raster][topology]") {
    std::mt19937 rng(7);
    const Affine maps[] = {Affine::scale(1e-3, 1e-3), Affine::scale(-3, 2),
                           Affine::rotate(0.7) * Affine::translate(1e6, -5e5), Affine{0.5, 0.1, -0.2, 0.9, 3, 4}};
    for (int trial = 0; trial < 60; ++trial) {
        const ref::Contour c = testing::random_polygon(rng, Rect{0, 0, 50, 50}, 3 + trial % 6);
        const Path p = ref::to_path({c});
        const Topology t = classify_topology(p);
        for (const Affine& m : maps) CHECK(classify_topology(p.transformed(m)) == t);
    }
}

TEST_CASE("topology: random shapes classified Simple render plainly within the exact bound", "[raster][topology]") {
    std::mt19937 rng(1234);
    Rasterizer r;
    int simple = 0, overlapping = 0;
    for (int trial = 0; trial < 300; ++trial) {
        ref::Contours cs;
        const int n = 1 + trial % 3;
        for (int k = 0; k < n; ++k) {
            if (trial % 2)
                cs.push_back(testing::random_simple_polygon(rng, {12.0 + 9 * k, 14.0 + 5 * k}, 2, 9, 5 + k));
            else
                cs.push_back(testing::random_polygon(rng, Rect{1, 1, 30, 30}, 3 + trial % 4));
        }
        const Path p = ref::to_path(cs);
        const Topology t = classify_topology(p);
        (t == Topology::Simple ? simple : overlapping)++;
        if (t != Topology::Simple) continue;
        const IRect clip{0, 0, 40, 40};
        FillOptions plain;
        plain.exact_overlaps = false;
        for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            plain.rule = rule;
            const auto out = render(r, p, Affine::identity(), plain, clip);
            const auto cmp = compare(out, ref::slab_area(cs, rule, clip));
            INFO("trial " << trial << ": " << cmp.text());
            CHECK(cmp.max_err <= 1.0);
        }
    }
    // Both verdicts occur, so both branches above are exercised.
    CHECK(simple > 50);
    CHECK(overlapping > 50);
}

TEST_CASE("topology: DejaVu Sans glyphs, Simple ones render plainly within the exact bound", "[raster][topology]") {
    testing::GlyphFont font(testing::dejavu_sans_path());
    Rasterizer r;
    int simple = 0, total = 0;
    std::string overlapping;
    for (char32_t cp = 0x21; cp < 0x180; ++cp) {
        if (cp >= 0x7f && cp < 0xa1) continue;
        Path glyph;
        font.append_glyph(cp, 1000.0, {0, 0}, glyph);  // classified at one scale ...
        if (glyph.empty()) continue;
        ++total;
        const Topology t = classify_topology(glyph);
        if (t != Topology::Simple) {
            overlapping += std::to_string(static_cast<unsigned>(cp)) + " ";
            continue;
        }
        ++simple;
        // Rendered at another scale, plainly and through the exact cells (the same flattening):
        // they must agree to rounding.
        Path small;
        font.append_glyph(cp, 23.0, {2.3, 25.6}, small);
        const IRect clip{0, 0, 32, 32};
        FillOptions plain, cells;
        plain.exact_overlaps = false;
        cells.topology = Topology::Overlapping;
        const auto a = render(r, small, Affine::identity(), plain, clip);
        const auto b = render(r, small, Affine::identity(), cells, clip);
        int worst = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) worst = std::max(worst, std::abs(a.at(x, y) - b.at(x, y)));
        INFO("U+" << std::hex << static_cast<unsigned>(cp));
        CHECK(worst <= 1);
    }
    INFO("overlapping: " << overlapping);
    // About 3 % of DejaVu Sans glyphs have crossing contours (cedilla, ogonek and horn components).
    CHECK(simple >= total * 85 / 100);
    CHECK(simple < total);
}

TEST_CASE("topology: the rasterizer uses the verdict and the caller's verdict", "[raster][topology]") {
    Rasterizer r;
    Mask m;
    // Without a verdict: the winding sweep.
    const Path stacked = join(square(1.5, 1.5, 8), square(1.5, 1.5, 8));
    m = r.fill_mask(stacked, Affine::identity());
    CHECK(r.last_stats().topology == Topology::Unknown);
    CHECK(r.last_stats().swept);
    CHECK(m.at(1, 1) == 64);
    // The same through the overlap check.
    FillOptions cells;
    cells.winding_sweep = false;
    m = r.fill_mask(stacked, Affine::identity(), cells);
    CHECK(!r.last_stats().swept);
    CHECK(r.last_stats().exact_cells > 0);
    CHECK(m.at(1, 1) == 64);  // a quarter of the pixel, not half (the two copies do not add up)
    FillOptions classified;
    classified.topology = classify_topology(stacked);
    m = r.fill_mask(stacked, Affine::identity(), classified);
    CHECK(r.last_stats().topology == Topology::Overlapping);
    CHECK(m.at(1, 1) == 64);
    classified.topology = classify_topology(square(1, 1, 8));
    m = r.fill_mask(square(1, 1, 8), Affine::identity(), classified);
    CHECK(r.last_stats().topology == Topology::Simple);
    CHECK(r.last_stats().exact_cells == 0);
    // A caller's Simple verdict is trusted: the stacked copy then adds up (which is why the verdict
    // must come from classify_topology).
    FillOptions trusted;
    trusted.topology = Topology::Simple;
    m = r.fill_mask(stacked, Affine::identity(), trusted);
    CHECK(r.last_stats().topology == Topology::Simple);
    CHECK(m.at(1, 1) == 128);
    // Exact overlaps off: no verdict is taken.
    FillOptions off;
    off.exact_overlaps = false;
    m = r.fill_mask(stacked, Affine::identity(), off);
    CHECK(r.last_stats().topology == Topology::Unknown);
}

TEST_CASE("topology: the rasterizer classifies shapes large for their number of segments", "[raster][topology]") {
    Rasterizer r;
    const IRect clip{0, 0, 300, 300};
    // Shapes the winding sweep does not take are classified (the sweep proves or cuts the others
    // without a verdict).
    FillOptions exact;
    exact.winding_sweep = false;
    // A ring: classified Simple, accumulated plainly, and within 1/255 of the per-cell check on
    // the same outline.
    const Path rings = ring();
    auto out = render(r, rings, Affine::identity(), exact, clip);
    CHECK(r.last_stats().topology == Topology::Simple);
    CHECK(r.last_stats().exact_cells == 0);
    FillOptions checked;  // the per-cell check on the same flattened outline
    checked.topology = Topology::Overlapping;
    checked.winding_sweep = false;
    const auto with_check = render(r, rings, Affine::identity(), checked, clip);
    CHECK(max_difference(out, with_check) <= 1);
    // With the sweep: not classified, proven simple by the sweep, the same pixels.
    const auto swept = render(r, rings, Affine::identity(), {}, clip);
    CHECK(r.last_stats().topology == Topology::Unknown);
    CHECK(r.last_stats().swept_simple);
    CHECK(r.last_stats().exact_cells == 0);
    CHECK(max_difference(swept, with_check) <= 1);
    // Two large squares stacked: classified Overlapping, and exact (a stacked copy adds nothing),
    // through the per-cell check and through the sweep.
    const Path stacked = join(square(20.25, 20.25, 200), square(20.25, 20.25, 200));
    const auto reference = ref::path_reference(square(20.25, 20.25, 200), Affine::identity(), FillRule::NonZero, clip);
    out = render(r, stacked, Affine::identity(), exact, clip);
    CHECK(r.last_stats().topology == Topology::Overlapping);
    CHECK(r.last_stats().exact_cells > 0);
    for (const FillOptions& o : {exact, FillOptions{}}) {
        out = render(r, stacked, Affine::identity(), o, clip);
        CHECK(r.last_stats().swept == o.winding_sweep);
        const auto cmp = compare(out, reference);
        INFO(cmp.text());
        CHECK(cmp.max_err <= 1.0);
        CHECK(out.at(20, 100) == 191);  // three quarters of the pixel, not clamped double coverage (255)
    }
    // A glyph-sized box with as many segments: not classified (the per-cell check is cheaper).
    (void)render(r, join(square(1.5, 1.5, 8), square(1.5, 1.5, 8)), Affine::identity(), exact, clip);
    CHECK(r.last_stats().topology == Topology::Unknown);
    CHECK(r.last_stats().exact_cells > 0);
}

TEST_CASE("topology: decide_topology is the verdict fill reaches for a shape given none", "[raster][topology]") {
    Rasterizer r;
    const IRect clip{0, 0, 300, 300};
    FillOptions exact;  // a shape the winding sweep does not take
    exact.winding_sweep = false;
    const Path rings = ring();
    const Path stacked = join(square(20.25, 20.25, 200), square(20.25, 20.25, 200));
    const Path small = join(square(1.5, 1.5, 8), square(1.5, 1.5, 8));
    // Boxes as fill() sees them: the control bounds in whole pixels.
    CHECK(decide_topology(rings, Affine::identity(), exact.tolerance, 243, 243) == Topology::Simple);
    CHECK(decide_topology(stacked, Affine::identity(), exact.tolerance, 201, 201) == Topology::Overlapping);
    CHECK(decide_topology(small, Affine::identity(), exact.tolerance, 9, 9) == Topology::Unknown);
    for (const Path* p : {static_cast<const Path*>(&rings), &stacked, &small}) {
        const Rect b = p->control_bounds();
        const double bw = std::ceil(b.x1) - std::floor(b.x0), bh = std::ceil(b.y1) - std::floor(b.y0);
        const Topology decided = decide_topology(*p, Affine::identity(), exact.tolerance, bw, bh);
        (void)render(r, *p, Affine::identity(), exact, clip);
        CHECK(r.last_stats().topology == decided);
        // Passing the decided verdict renders the same pixels as letting fill() decide.
        const auto by_fill = render(r, *p, Affine::identity(), exact, clip);
        FillOptions given = exact;
        given.topology = decided;
        const auto by_caller = render(r, *p, Affine::identity(), given, clip);
        CHECK(max_difference(by_fill, by_caller) == 0);
    }
    // Under a similarity map the verdict is the one for that map's flattening, with the tolerance in
    // the path's units: a scale of 2 halves it.
    const Affine twice = Affine::scale(2, 2);
    CHECK(decide_topology(rings, twice, exact.tolerance, 486, 486) == classify_topology(rings, exact.tolerance / 2));
}

TEST_CASE("topology: the glyph cache hands each glyph's verdict to the rasterizer", "[raster][topology][text]") {
    const Font font = Font::load(testing::dejavu_sans_path());
    GlyphCache cache(1u << 20, kDefaultTolerance);
    Rasterizer r;
    const Mask& o = cache.mask(font, font.glyph_index(U'o'), 20.0, {0, 0}, r);
    CHECK(r.last_stats().topology == Topology::Simple);
    CHECK(r.last_stats().exact_cells == 0);
    CHECK(!o.data.empty());
    // A c with cedilla: the cedilla component crosses the c (DejaVu Sans).
    (void)cache.mask(font, font.glyph_index(U'\u00e7'), 20.0, {0, 0}, r);
    CHECK(r.last_stats().topology == Topology::Overlapping);
    // Another size of the same glyph keeps the verdict decided once.
    (void)cache.mask(font, font.glyph_index(U'o'), 33.0, {0.5, 0}, r);
    CHECK(r.last_stats().topology == Topology::Simple);
}

TEST_CASE("regression: classify_topology attempts no proof for extreme conic weights or scales", "[raster][topology]") {
    // fuzz/regressions/raster/conic-weight-1e154-splits-to-infinity: splitting a conic of weight
    // 9.5e153 made infinite control points, which the pairing grid converted to int (undefined
    // behaviour; the sanitizer builds stop on it).
    Path conic;
    conic.move_to(100.75, -97.3).conic_to({-45.7, 208}, {167.9, -163.4}, 9.48075e153).close();
    CHECK(classify_topology(conic) == Topology::Overlapping);
    // The rasterizer classifies it itself (a large box for two verbs) and fills it exactly or
    // refuses it, without undefined behaviour.
    Rasterizer r;
    try {
        (void)r.fill_mask(conic, Affine::scale(2, 2));
    } catch (const Error& e) { CHECK(e.kind() != ErrorKind::Io); }
    // Coordinates beyond 2^500 or an extent below 2^-500: no proof either.
    CHECK(classify_topology(square(0, 0, 1).transformed(Affine::scale(1e300, 1e300))) == Topology::Overlapping);
    CHECK(classify_topology(square(0, 0, 1).transformed(Affine::scale(1e-300, 1e-300))) == Topology::Overlapping);
    CHECK(classify_topology(square(0, 0, 1).transformed(Affine::scale(1e100, 1e100))) == Topology::Simple);
}

TEST_CASE("topology: verdicts after a path large enough to free the classifier's buffers", "[raster][topology]") {
    // A simple ring of 2^17 + 1 edges (past the buffers a thread keeps), then a crossing pair and a
    // simple square: each verdict as when classified alone.
    Path ring;
    const int n = (1 << 17) + 1;
    for (int i = 0; i < n; ++i) {
        const double t = 2 * kPi * i / n;
        const Point q{1000 * std::cos(t), 1000 * std::sin(t)};
        if (i == 0)
            ring.move_to(q);
        else
            ring.line_to(q);
    }
    ring.close();
    CHECK(classify_topology(ring) == Topology::Simple);
    CHECK(classify_topology(polygon({{0, 0}, {10, 10}, {10, 0}, {0, 10}})) == Topology::Overlapping);
    CHECK(classify_topology(square(0, 0, 10)) == Topology::Simple);
    CHECK(classify_topology(join(ring, ring)) == Topology::Overlapping);
    CHECK(classify_topology(square(0, 0, 10)) == Topology::Simple);
}

namespace {

// The largest |difference| between plain accumulation and the exact cells for `p` mapped by `m`
// at flattening tolerance `tol` (the same flattening in both).
int plain_vs_cells(Rasterizer& r, const Path& p, const Affine& m, double tol) {
    FillOptions plain, cells;
    plain.tolerance = cells.tolerance = tol;
    plain.exact_overlaps = false;
    cells.topology = Topology::Overlapping;
    const Mask a = r.fill_mask(p, m, plain), b = r.fill_mask(p, m, cells);
    REQUIRE(a.bounds.x0 == b.bounds.x0);
    REQUIRE(a.bounds.y0 == b.bounds.y0);
    REQUIRE(a.data.size() == b.data.size());
    int worst = 0;
    for (std::size_t i = 0; i < a.data.size(); ++i) worst = std::max(worst, std::abs(a.data[i] - b.data[i]));
    return worst;
}

// Similarity maps of scale s: turned, mirrored or not, at a fractional offset.
Affine similarity(double s, double angle, bool mirror, Point at) {
    const double c = std::cos(angle) * s, k = std::sin(angle) * s, f = mirror ? -1 : 1;
    return Affine{c, k, -f * k, f * c, at.x, at.y};
}

// A box (clockwise, y up) under a cubic arch from (0, 0) to (100, 0) that rises to y = 30.
Path arch_box() {
    Path p;
    p.move_to({0, 0});
    p.cubic_to({0, 40}, {100, 40}, {100, 0});
    p.line_to({100, -100});
    p.line_to({0, -100});
    p.close();
    return p;
}

// The box and a hole (opposite orientation) reaching up to just under the arch. The curves are
// apart, but where the arch is flattened to few chords they cut through the hole.
Path arch_over_hole() {
    Path p = arch_box();
    p.move_to({47, -50});
    p.line_to({53, -50});
    p.line_to({53, 29.4});
    p.line_to({47, 29.4});
    p.close();
    return p;
}

}  // namespace

TEST_CASE("topology: under similarity maps, a hole under an arch is Simple only while the flattening keeps clear of it",
          "[raster][topology]") {
    const Path p = arch_over_hole();
    CHECK(classify_topology(p) == Topology::Overlapping);  // the arch's hull holds the hole's top
    Rasterizer r;
    int simple = 0, refused_and_needed = 0;
    for (double lambda : {0.01, 0.1, 0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 8.0, 12.0, 20.0, 40.0, 80.0, 100.0}) {
        const Topology t = classify_topology(p, lambda);
        for (int k = 0; k < 4; ++k) {
            const double s = 0.4 * (1 + k);  // the same tolerance in path units at four scales
            const Affine m = similarity(s, 0.7 * k, k & 1, {10.3 + k, 30.7});
            const int worst = plain_vs_cells(r, p, m, lambda * s);
            INFO("lambda " << lambda << ", scale " << s);
            if (t == Topology::Simple)
                CHECK(worst <= 1);
            else if (worst > 1)
                ++refused_and_needed;
        }
        simple += t == Topology::Simple;
    }
    // Fine flattenings are proven: the hole's top is 0.6 below the arch, so a flattening within
    // 0.5 of the arch keeps clear of it. Coarse ones are refused, and there plain accumulation is
    // wrong.
    CHECK(classify_topology(p, 0.5) == Topology::Simple);
    CHECK(classify_topology(p, 0.7) == Topology::Overlapping);
    CHECK(classify_topology(p, 40.0) == Topology::Overlapping);
    CHECK(simple == 3);
    CHECK(refused_and_needed >= 4);
    CHECK_THROWS_AS(classify_topology(p, 0.0), Error);
    CHECK_THROWS_AS(classify_topology(p, NAN), Error);
}

TEST_CASE("topology: under similarity maps, a hole lying between an arch and its chord is refused at every tolerance",
          "[raster][topology]") {
    // No chord of the arch ever crosses the hole, but where the arch is one chord the hole lies
    // outside the flattened box: its winding number there is -1 beside the box's +1, which plain
    // accumulation cancels. Its winding number cannot be read from a point outside the arch's
    // hull, so no tolerance is proven.
    Path p = arch_box();
    p.move_to({45, 1});
    p.line_to({55, 1});
    p.line_to({55, 20});
    p.line_to({45, 20});
    p.close();
    Rasterizer r;
    for (double lambda : {0.1, 1.0, 10.0, 100.0}) CHECK(classify_topology(p, lambda) == Topology::Overlapping);
    CHECK(plain_vs_cells(r, p, similarity(0.4, 0, true, {10.3, 30.7}), 100 * 0.4) > 100);
}

TEST_CASE("topology: Linux Libertine glyphs Simple under similarity maps render plainly like the exact cells",
          "[raster][topology][text]") {
    const Font font = Font::load(std::string(CASTELJAU_SOURCE_DIR) + "/fonts/LinLibertine_R.otf");
    const double upem = 1 / font.glyph_transform(1, {0, 0}).a;
    const double lambda = kDefaultTolerance * upem / 12;  // proven for 12 px and up
    Rasterizer r;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    int any = 0, similar = 0, total = 0;
    for (char32_t cp = 0x21; cp < 0x17f; ++cp) {
        const Path glyph = font.glyph_path(font.glyph_index(cp));
        if (cp >= 0x7f && cp < 0xa1) continue;
        if (glyph.empty()) continue;
        ++total;
        const Topology general = classify_topology(glyph), t = classify_topology(glyph, lambda);
        if (general == Topology::Simple) CHECK(t == Topology::Simple);  // it proves more, never less
        any += general == Topology::Simple;
        if (t != Topology::Simple) continue;
        ++similar;
        if (general == Topology::Simple) continue;
        // Rendered at 12 to 100 px, turned and mirrored: plain accumulation is exact.
        for (int k = 0; k < 3; ++k) {
            const double px = 12 * std::exp(unit(rng) * std::log(100.0 / 12));
            const Affine m = similarity(px / upem, unit(rng) * 6.283, k & 1, {60 + unit(rng), 60 + unit(rng)});
            INFO("U+" << std::hex << static_cast<unsigned>(cp) << std::dec << " at " << px << " px");
            CHECK(plain_vs_cells(r, glyph, m, kDefaultTolerance) <= 1);
        }
    }
    INFO(total << " glyphs: " << any << " Simple under any map, " << similar << " under similarity maps");
    // Thin CFF curves have control hulls reaching across their strokes: half the glyphs (158 of
    // 316) are proven under every map, nearly all (313) under the similarity maps glyphs are drawn
    // with, where curves farther apart than their tolerance bands cannot meet; each contour's
    // orientation must then be decided with the slack of those bands (with whole segment hulls
    // only 281 would be).
    CHECK(similar >= total * 97 / 100);
    CHECK(any < total * 60 / 100);
}

TEST_CASE("topology: the glyph cache gives the similarity verdict from a glyph's second mask, or at once when large",
          "[raster][topology][text]") {
    const Font font = Font::load(std::string(CASTELJAU_SOURCE_DIR) + "/fonts/LinLibertine_R.otf");
    const std::uint32_t o = font.glyph_index(U'o'), e = font.glyph_index(U'e');
    REQUIRE(classify_topology(font.glyph_path(o)) == Topology::Overlapping);
    REQUIRE(classify_topology(font.glyph_path(e)) == Topology::Overlapping);
    GlyphCache cache(1u << 20, kDefaultTolerance);
    Rasterizer r;
    (void)cache.mask(font, o, 24.0, {0, 0}, r);  // first mask: the verdict for every map
    CHECK(r.last_stats().topology == Topology::Overlapping);
    (void)cache.mask(font, o, 24.0, {0.25, 0}, r);  // second: the verdict for similarity maps
    CHECK(r.last_stats().topology == Topology::Simple);
    CHECK(r.last_stats().exact_cells == 0);
    (void)cache.mask(font, o, 12.0, {0.5, 0}, r);  // half the size: it still holds
    CHECK(r.last_stats().topology == Topology::Simple);
    (void)cache.mask(font, o, 3.0, {0, 0}, r);  // decided again for 3 px
    CHECK(r.last_stats().topology != Topology::Unknown);
    (void)cache.mask(font, e, 100.0, {0, 0}, r);  // large: at once
    CHECK(r.last_stats().topology == Topology::Simple);
}

TEST_CASE("topology: the rasterizer classifies a path under a similarity map with the similarity verdict",
          "[raster][topology][text]") {
    const Font font = Font::load(std::string(CASTELJAU_SOURCE_DIR) + "/fonts/LinLibertine_R.otf");
    const Path o = font.glyph_path(font.glyph_index(U'o'));
    REQUIRE(classify_topology(o) == Topology::Overlapping);
    Rasterizer r;
    const double s = 500 * font.glyph_transform(1, {0, 0}).a;  // 500 px: large enough to be classified
    FillOptions unswept;                                       // (the sweep takes it unclassified)
    unswept.winding_sweep = false;
    (void)r.fill_mask(o, Affine{s, 0, 0, -s, 10, 600}, unswept);
    CHECK(r.last_stats().topology == Topology::Simple);
    (void)r.fill_mask(o, Affine::rotate(0.5) * Affine{-s, 0, 0, -s, 10, 600}, unswept);
    CHECK(r.last_stats().topology == Topology::Simple);
    // A shear flattens differently: only the verdict for every map applies.
    (void)r.fill_mask(o, Affine::skew_x(0.3) * Affine{s, 0, 0, -s, 10, 600}, unswept);
    CHECK(r.last_stats().topology == Topology::Overlapping);
}

TEST_CASE("regression: a two-segment contour's curve is not halved for the proof", "[raster][topology]") {
    // Two copies of a contour of one quadratic and its closing line, 0.328 px apart: the curves
    // keep clear of each other by 0.016 px, but at 0.5 px the area-balanced polygon's vertex (off
    // the curve, towards the control point) reaches into the other copy. Halving the curve to give
    // the contour three segments would make each half's hull look apart, though the flattener's
    // chords and vertices span the whole curve (plain accumulation 152 against the exact 150).
    Path p;
    for (double dy : {0.0, 0.328125}) {
        p.move_to({21.15625, 23.046875 + dy});
        p.quad_to({24.265625, 23.890625 + dy}, {24.265625, 23.265625 + dy});
        p.close();
    }
    Rasterizer r;
    for (double tol : {kDefaultTolerance, 0.1, 0.5, 2.0}) {
        INFO("tolerance " << tol);
        const int worst = plain_vs_cells(r, p, Affine{}, tol);
        if (classify_topology(p) == Topology::Simple) CHECK(worst <= 1);
        if (classify_topology(p, tol) == Topology::Simple) CHECK(worst <= 1);
    }
    CHECK(plain_vs_cells(r, p, Affine{}, 0.5) > 1);  // the copies do overlap at 0.5 px
}
