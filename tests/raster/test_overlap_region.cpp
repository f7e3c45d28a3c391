// find_overlap_region (src/raster/overlap_region.cpp) and FillOptions::overlap_boxes: the overlap
// check confined to the boxes of the segments that may need it must still give every pixel its
// exact coverage, checked against the independent exact-area reference; and the analysis must
// find what it claims on shapes whose winding numbers are known by construction.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "casteljau/raster.hpp"
#include "raster_check.hpp"
#include "reference_area.hpp"

using namespace casteljau;
using casteljau::testing::compare;
using casteljau::testing::join;
using casteljau::testing::polygon;
using casteljau::testing::render;
using casteljau::testing::square;

namespace {

bool covers(const std::vector<Rect>& boxes, Point p) {
    return std::any_of(boxes.begin(), boxes.end(),
                       [&](const Rect& b) { return p.x >= b.x0 && p.x <= b.x1 && p.y >= b.y0 && p.y <= b.y1; });
}

}  // namespace

TEST_CASE("overlap region: shapes whose winding numbers are known", "[raster][overlap_region]") {
    // A square, and a square with a hole of the other orientation: windings 0 and 1 only.
    OverlapRegion r = find_overlap_region(square(0, 0, 10));
    CHECK(r.topology == Topology::Simple);
    CHECK(r.boxes.empty());
    r = find_overlap_region(join(square(0, 0, 10), square(3, 3, 4, false)));
    CHECK(r.topology == Topology::Simple);
    // The same hole with the exterior's orientation: winding 2 inside it, so its four segments
    // are bad, and the exterior's are not.
    r = find_overlap_region(join(square(0, 0, 10), square(3, 3, 4)));
    CHECK(r.topology == Topology::Overlapping);
    CHECK(covers(r.boxes, {5, 3}));
    CHECK(covers(r.boxes, {3, 5}));
    CHECK_FALSE(covers(r.boxes, {0, 5}));
    CHECK_FALSE(covers(r.boxes, {5, 10}));
    // A bow tie: its two crossing segments meet.
    r = find_overlap_region(polygon({{0, 0}, {10, 10}, {10, 0}, {0, 10}}));
    CHECK(r.topology == Topology::Overlapping);
    CHECK(covers(r.boxes, {5, 5}));
    // Two squares sharing an edge, both clockwise: the shared edge's segments meet (they run
    // along each other), the far sides do not.
    r = find_overlap_region(join(square(0, 0, 10), square(10, 0, 10)));
    CHECK(r.topology == Topology::Overlapping);
    CHECK(covers(r.boxes, {10, 5}));
    CHECK_FALSE(covers(r.boxes, {0, 5}));
    CHECK_FALSE(covers(r.boxes, {20, 5}));
    // Curves are not analysed.
    Path curved;
    curved.move_to({0, 0});
    curved.quad_to({5, 10}, {10, 0});
    curved.close();
    CHECK(find_overlap_region(curved).topology == Topology::Unknown);
}

TEST_CASE("overlap region: random lattice polygons filled with their boxes are exact", "[raster][overlap_region]") {
    // Vertices on a 6 x 6 lattice: contours touch, cross, run along each other and wind twice.
    // Filled with the overlap check confined to the analysis' boxes (or plainly when it proves
    // them simple), every pixel must keep the exact coverage, under both rules, against the
    // independent reference.
    std::mt19937 rng(33);
    std::uniform_int_distribution<int> coord(0, 5);
    Rasterizer r;
    const Affine m = Affine::translate(0.3, 0.45) * Affine::scale(3.1, 2.9);
    const IRect clip{0, 0, 20, 20};
    FillOptions plain;
    plain.exact_overlaps = false;
    int simple = 0, confined = 0, plain_wrong = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        ref::Contours cs(1 + trial % 3);
        for (ref::Contour& c : cs) {
            const int n = 3 + static_cast<int>(rng() % 5);
            for (int k = 0; k < n; ++k) c.push_back({double(coord(rng)), double(coord(rng))});
        }
        const Path p = ref::to_path(cs).transformed(m);
        const OverlapRegion region = find_overlap_region(p);
        REQUIRE(region.topology != Topology::Unknown);
        simple += region.topology == Topology::Simple;
        confined += !region.boxes.empty();
        FillOptions fo;
        fo.winding_sweep = false;
        fo.topology = region.topology;
        fo.overlap_boxes = region.boxes;
        for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            fo.rule = plain.rule = rule;
            const ref::CoverageGrid truth = ref::slab_area(ref::transformed(cs, m), rule, clip);
            const auto cmp = compare(render(r, p, Affine{}, fo, clip), truth);
            INFO("trial " << trial << ": " << cmp.text());
            CHECK(cmp.max_err <= 1.0);
            plain_wrong += compare(render(r, p, Affine{}, plain, clip), truth).max_err > 1.0;
        }
    }
    CHECK(simple > 100);
    CHECK(confined > 500);
    CHECK(plain_wrong > 300);  // shapes where the confined check has something to correct
}

TEST_CASE("overlap region: boxes found in one frame keep the fill exact in another", "[raster][overlap_region]") {
    // What render_map's MapCache relies on: meetings and winding numbers do not change under an
    // affine map, so the boxes found for a path in one frame, mapped into another, still hold
    // every segment that may need the check there.
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> coord(0, 5);
    const Affine found_in = Affine::translate(1e4, -3e3) * Affine::scale(-37.5, 61.25);
    const Affine frames[] = {Affine::translate(0.3, 0.45) * Affine::scale(3.1, 2.9),
                             Affine::translate(19.7, 0.2) * Affine::scale(-3.3, 3.3),
                             Affine{2.5, 0.4, -0.6, 2.7, 4.1, 1.3}};
    const std::optional<Affine> back = found_in.inverse();
    REQUIRE(back);
    Rasterizer r;
    const IRect clip{0, 0, 24, 24};
    int confined = 0;
    for (int trial = 0; trial < 600; ++trial) {
        ref::Contours cs(1 + trial % 3);
        for (ref::Contour& c : cs)
            for (int k = 0; k < 3 + trial % 5; ++k) c.push_back({double(coord(rng)), double(coord(rng))});
        const Path p = ref::to_path(cs);
        const OverlapRegion found = find_overlap_region(p.transformed(found_in));
        REQUIRE(found.topology != Topology::Unknown);
        confined += !found.boxes.empty();
        for (const Affine& frame : frames) {
            const Affine to_frame = frame * *back;
            std::vector<Rect> boxes;
            for (const Rect& b : found.boxes) boxes.push_back(to_frame.map_bounds(b));
            FillOptions fo;
            fo.winding_sweep = false;
            fo.topology = found.topology;
            fo.overlap_boxes = boxes;
            const auto cmp = compare(render(r, p, frame, fo, clip),
                                     ref::slab_area(ref::transformed(cs, frame), FillRule::NonZero, clip));
            INFO("trial " << trial << ": " << cmp.text());
            CHECK(cmp.max_err <= 1.0);
        }
    }
    CHECK(confined > 200);
}

TEST_CASE("overlap region: stacked copies are left undecided rather than paired quadratically",
          "[raster][overlap_region]") {
    // 2,000 copies of one 40-gon: every cell holds thousands of segments, about 2e8 pairs to test.
    // The analysis stops at its linear budget and leaves the path to the overlap check.
    Path ring;
    for (int k = 0; k < 40; ++k) {
        const double t = 6.283185307179586 * k / 40;
        const Point q{50 + 40 * std::cos(t), 50 + 40 * std::sin(t)};
        if (k == 0)
            ring.move_to(q);
        else
            ring.line_to(q);
    }
    ring.close();
    Path stacked;
    for (int c = 0; c < 2000; ++c) stacked.append(ring);
    CHECK(find_overlap_region(stacked).topology == Topology::Unknown);
    // A few copies are analysed: every segment meets its copies.
    Path three;
    for (int c = 0; c < 3; ++c) three.append(ring);
    const OverlapRegion r = find_overlap_region(three);
    CHECK(r.topology == Topology::Overlapping);
    CHECK(r.boxes.size() == 120);
}

TEST_CASE("overlap region: a star of long crossing segments fills exactly with its boxes", "[raster][overlap_region]") {
    // 101 points on a circle joined 50 apart: every segment crosses dozens of others, and the
    // boxes cover the shape many times over, so the fill ignores them and checks everywhere.
    ref::Contour star;
    for (int k = 0; k < 101; ++k) {
        const double t = 6.283185307179586 * ((k * 50) % 101) / 101;
        star.push_back({20.25 + 18 * std::cos(t), 20.5 + 18 * std::sin(t)});
    }
    const Path p = ref::to_path({star});
    const OverlapRegion region = find_overlap_region(p);
    REQUIRE(region.topology == Topology::Overlapping);
    CHECK(region.boxes.size() == 101);
    Rasterizer r;
    const IRect clip{0, 0, 41, 41};
    FillOptions fo;
    fo.winding_sweep = false;
    fo.topology = region.topology;
    fo.overlap_boxes = region.boxes;
    for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
        fo.rule = rule;
        const auto cmp = compare(render(r, p, Affine{}, fo, clip), ref::slab_area({star}, rule, clip));
        INFO(cmp.text());
        CHECK(cmp.max_err <= 1.0);
    }
}
