// SharedBorders (casteljau/map.hpp): what it drops and keeps, and that stroking what it keeps (Butt
// caps) covers exactly what stroking every ring covers, on the Natural Earth world and on cases
// built to break it (four countries at one point, rings touching at a vertex, spikes, repeats).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <random>
#include <set>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/map.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/round_stroke.hpp"
#include "casteljau/stroke.hpp"
#include "map_test_util.hpp"
#include "map/unique_segments.hpp"

using namespace casteljau;

namespace {

Path ring(std::initializer_list<Point> pts) {
    Path p;
    p.add_polygon(std::vector<Point>(pts), true);
    return p;
}

std::size_t segments_in(const Path& p) {
    std::size_t n = 0;
    for (Verb v : p.verbs()) n += v == Verb::Line;
    return n;
}

std::size_t closes_in(const Path& p) {
    return static_cast<std::size_t>(std::count(p.verbs().begin(), p.verbs().end(), Verb::Close));
}

// Largest coverage difference between stroking every path as it is and stroking what SharedBorders
// keeps of them (in order) with Butt caps, filled as one path each, nonzero, over `clip`.
int union_difference(const std::vector<Path>& paths, const StrokeStyle& st, const IRect& clip,
                     std::size_t* kept = nullptr, std::size_t* total = nullptr) {
    Path all, once;
    SharedBorders borders;
    StrokeStyle butt = st;
    butt.cap = LineCap::Butt;
    std::size_t k = 0, t = 0;
    for (const Path& p : paths) {
        all.append(stroke(p, st));
        Path chains, whole;
        borders.add(p, chains, whole, stroke_merge_distance());
        k += segments_in(chains) + segments_in(whole);
        t += segments_in(p) + closes_in(p);
        once.append(stroke(chains, butt));
        once.append(stroke(whole, st));
    }
    if (kept) *kept = k;
    if (total) *total = t;
    Rasterizer r;
    const Mask a = r.fill_mask(all, Affine{}, FillOptions{}, clip);
    const Mask b = r.fill_mask(once, Affine{}, FillOptions{}, clip);
    int worst = 0;
    for (int y = clip.y0; y < clip.y1; ++y)
        for (int x = clip.x0; x < clip.x1; ++x) worst = std::max(worst, std::abs(int(a.at(x, y)) - int(b.at(x, y))));
    return worst;
}

const LineJoin kJoins[] = {LineJoin::Round, LineJoin::Miter, LineJoin::MiterClip, LineJoin::Bevel};

}  // namespace

TEST_CASE("SharedBorders: a border shared by two rings comes out once", "[map][stroke]") {
    SharedBorders b;
    Path first, second, whole;
    // The shared border is (50, 10) (52, 20) (48, 30) (50, 40).
    b.add(ring({{10, 10}, {50, 10}, {52, 20}, {48, 30}, {50, 40}, {10, 40}}), first, whole);
    CHECK(segments_in(first) == 5);  // a new ring is kept whole and closed: move, five lines, close
    CHECK(closes_in(first) == 1);
    // The neighbour runs the border the other way round. Its middle segment is dropped; the two
    // segments at the border's ends stay, because the joins there are new (the neighbour turns
    // differently), so it becomes one open chain from (52, 20) round to (48, 30).
    b.add(ring({{50, 10}, {90, 10}, {90, 40}, {50, 40}, {48, 30}, {52, 20}}), second, whole);
    CHECK(closes_in(second) == 0);
    REQUIRE(second.verbs().size() == 6);
    CHECK(second.points()[0] == Point{52, 20});
    CHECK(second.points()[5] == Point{48, 30});
    // The same ring again, in either direction and from another start: nothing new at all.
    Path again, reversed;
    b.add(ring({{90, 40}, {50, 40}, {48, 30}, {52, 20}, {50, 10}, {90, 10}}), again, whole);
    b.add(ring({{90, 10}, {90, 40}, {50, 40}, {48, 30}, {52, 20}, {50, 10}}).reversed(), reversed, whole);
    CHECK(again.empty());
    CHECK(reversed.empty());
    CHECK(whole.empty());
    // After clear() everything is new again.
    b.clear();
    Path fresh;
    b.add(ring({{50, 10}, {90, 10}, {90, 40}, {50, 40}, {48, 30}, {52, 20}}), fresh, whole);
    CHECK(closes_in(fresh) == 1);
}

TEST_CASE("SharedBorders: open contours, curves and degenerate rings pass through unchanged", "[map][stroke]") {
    SharedBorders b;
    Path in;
    in.move_to(0, 0).line_to(10, 0).line_to(10, 10);  // open
    in.add_circle({50, 50}, 5);                       // curves
    in.move_to(70, 70).line_to(80, 70).close();       // a there-and-back ring
    Path chains, out;
    b.add(in, chains, out);
    CHECK(chains.empty());
    CHECK(std::vector<Verb>(out.verbs().begin(), out.verbs().end()) ==
          std::vector<Verb>(in.verbs().begin(), in.verbs().end()));
    CHECK(std::vector<Point>(out.points().begin(), out.points().end()) ==
          std::vector<Point>(in.points().begin(), in.points().end()));
    // Repeated positions carry no segment: this ring is the square above with repeats.
    SharedBorders c;
    Path a, dup, rest;
    c.add(ring({{10, 10}, {50, 10}, {50, 40}, {10, 40}}), a, rest);
    c.add(ring({{10, 10}, {10, 10}, {50, 10}, {50, 40}, {50, 40}, {10, 40}, {10, 10}}), dup, rest);
    CHECK(dup.empty());
    CHECK(rest.empty());
}

TEST_CASE("SharedBorders: stroking what is kept covers what every ring's stroke covers", "[map][stroke]") {
    const IRect clip{0, 0, 120, 100};
    // Four squares meeting at one point (the Four Corners): each join there is new, although both
    // of its segments were drawn by other rings.
    const std::vector<Path> four = {
        ring({{20, 20}, {60, 20}, {60, 50}, {20, 50}}), ring({{60, 20}, {100, 20}, {100, 50}, {60, 50}}),
        ring({{60, 50}, {100, 50}, {100, 80}, {60, 80}}), ring({{20, 50}, {60, 50}, {60, 80}, {20, 80}})};
    // Rings touching at a vertex with other neighbours, a spike, sharp turns, a partly shared
    // border that turns, a hole sharing its outline with an island inside it; a ring of one
    // position, one of two and one the stroker merges into a point (their strokes depend on the
    // caps) and an open line.
    Path line;
    line.move_to(5, 5).line_to(60, 12).line_to(20, 30);
    const std::vector<Path> mixed = {
        line,
        ring({{5, 90}, {5, 90}, {5, 90}}),
        ring({{100, 90}, {110, 95}}),
        ring({{10, 70}, {40, 68}}),
        ring({{115, 5}, {115 + 1e-6, 5}, {115, 5 + 2e-6}}),  // three positions the stroker merges: a dot
        ring({{10, 10}, {40, 12}, {70, 10}, {72, 40}, {70, 70}, {40, 68}, {10, 70}, {12, 40}}),
        ring({{70, 10}, {100, 25}, {72, 40}}),
        ring({{70, 70}, {72, 40}, {100, 55}, {110, 90}, {80, 60.5}}),
        ring({{10, 70}, {40, 68}, {41, 95}, {40.5, 68.2}, {60, 90}}),
        ring({{30, 30}, {50, 30}, {50, 50}, {30, 50}}),
        ring({{30, 30}, {30, 50}, {50, 50}, {50, 30}}),
    };
    for (LineJoin join : kJoins)
        for (double width : {0.8, 3.0, 9.0}) {
            StrokeStyle st;
            st.join = join;
            st.cap = join == LineJoin::Round ? LineCap::Round : LineCap::Square;
            st.width = width;
            st.miter_limit = 10;
            INFO("join " << int(join) << ", width " << width);
            CHECK(union_difference(four, st, clip) <= 1);
            CHECK(union_difference(mixed, st, clip) <= 1);
        }
}

TEST_CASE("SharedBorders: positions the stroker merges are merged before borders are compared", "[map][stroke]") {
    // A ring that visits O three times, then a run of it closed on itself, then the ring reversed
    // (fuzz_stroke's shapes). E lies a hair from O, so the stroker merges them, and the run
    // E, C, O becomes a there-and-back between O and C: its join at O turns back on itself, which
    // a miter join draws as a long spike and no other ring draws. The run must be kept whole.
    const Point O{60, 50}, D{10, 70}, E{60 + 1e-9, 50 + 1e-9}, C{30, 20}, B{59.98, 49.99}, A{55, 95};
    const Path r = ring({O, D, O, E, C, O, O, B, A});
    const std::vector<Path> rings = {r.reversed(), ring({E, C, O, O}), r};
    const IRect clip{0, 0, 120, 100};
    for (LineJoin join : kJoins)
        for (double width : {0.8, 5.25}) {
            StrokeStyle st;
            st.join = join;
            st.cap = LineCap::Round;
            st.width = width;
            st.miter_limit = 10;
            INFO("join " << int(join) << ", width " << width);
            CHECK(union_difference(rings, st, clip) <= 1);
        }
}

TEST_CASE("SharedBorders: the Natural Earth world, each border stroked once, same pixels", "[map][stroke]") {
    const MapData world = test::load_world();
    const test::EquirectFrame fr{1200, 600};
    std::vector<Path> features;
    for (const Feature& f : world.features) {
        Path p;
        for (const Geometry& g : f.geometries) {
            if (g.kind != GeometryKind::Polygons) continue;
            std::size_t start = 0;
            for (std::uint32_t end : g.ring_ends) {
                std::vector<std::vector<Point>> pieces;
                split_ring_at_antimeridian(std::span<const Point>(g.points).subspan(start, end - start), pieces);
                for (auto& piece : pieces) {
                    for (Point& q : piece) q = fr.px(q.x, q.y);
                    p.add_polygon(piece, true);
                }
                start = end;
            }
        }
        features.push_back(std::move(p));
    }
    for (LineJoin join : {LineJoin::Round, LineJoin::Miter}) {
        StrokeStyle st;
        st.join = join;
        st.width = 1.5;
        std::size_t kept = 0, total = 0;
        INFO("join " << int(join));
        CHECK(union_difference(features, st, IRect{0, 0, fr.w, fr.h}, &kept, &total) <= 1);
        // TopoJSON shares every border bit for bit. At 110m the borders are a few segments long,
        // and the two at either end of each stay (their joins are new): a fifth is dropped.
        CHECK(kept < total * 85 / 100);
        CHECK(kept > total / 2);
    }
}

TEST_CASE("drop_repeated_segments keeps one copy of each segment, either way round", "[map][shared]") {
    const LineSegment a{{1, 2}, {3, 4}}, b{{3, 4}, {5, 0}}, c{{0.0, 1}, {2, 2}}, dot{{7, 7}, {7, 7}};
    std::vector<LineSegment> segs{a, b, {a.b, a.a}, c, {{2, 2}, {-0.0, 1}}, dot, dot, b, {{3, 4}, {5, 1e-300}}};
    map_detail::drop_repeated_segments(segs);
    REQUIRE(segs.size() == 5);
    CHECK(segs[0].a == a.a);
    CHECK(segs[1].b == b.b);
    CHECK(segs[2].a == c.a);
    CHECK(segs[3].a == dot.a);
    CHECK(segs[4].b.y == 1e-300);  // differs from b by one bit: kept
    // Many segments, each drawn three times in shuffled directions: one of each stays, and the
    // round strokes of both lists are the same pixels.
    std::vector<LineSegment> many, once;
    for (int i = 0; i < 2000; ++i) once.push_back({{0.37 * i, 5 + std::sin(i)}, {0.37 * i + 0.4, 5 + std::cos(i)}});
    for (int k = 0; k < 3; ++k)
        for (const LineSegment& s : once) many.push_back(k == 1 ? LineSegment{s.b, s.a} : s);
    map_detail::drop_repeated_segments(many);
    REQUIRE(many.size() == once.size());
    std::size_t moved = 0;  // the first copies stay, in order
    for (std::size_t i = 0; i < once.size(); ++i) moved += !(many[i].a == once[i].a && many[i].b == once[i].b);
    CHECK(moved == 0);
    const IRect clip{0, 0, 740, 12};
    CHECK(round_stroke_mask(many, 0.4, clip).data == round_stroke_mask(once, 0.4, clip).data);
}

TEST_CASE("drop_repeated_segments matches a set of the first copies on 100,000 segments", "[map][shared]") {
    // Ends on a 12 x 12 grid (the second half a pixel off): four segments in five repeat an earlier
    // one, half of them the other way round.
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coord(0, 11);
    std::vector<LineSegment> segs, expected;
    std::set<std::array<double, 4>> seen;
    for (int i = 0; i < 100000; ++i) {
        const Point a{double(coord(rng)), double(coord(rng))}, b{double(coord(rng)) + 0.5, double(coord(rng))};
        segs.push_back(i % 2 ? LineSegment{a, b} : LineSegment{b, a});
        if (seen.insert({a.x, a.y, b.x, b.y}).second) expected.push_back(segs.back());
    }
    map_detail::drop_repeated_segments(segs);
    REQUIRE(segs.size() == expected.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < segs.size(); ++i) differ += !(segs[i].a == expected[i].a && segs[i].b == expected[i].b);
    CHECK(differ == 0);
}
