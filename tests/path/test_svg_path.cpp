// Tests for SVG path data parsing and formatting and points lists
// (include/casteljau/svg_path.hpp); SVG arcs are tested in test_arc.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "casteljau/arc.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/svg_path.hpp"
#include "svg_path_test_util.hpp"

using namespace casteljau;
using namespace svg_path_test;

namespace {}  // namespace

// ---------------------------------------------------------------------------------------------
// Commands, absolute and relative

TEST_CASE("svg path: moveto with implicit lineto, absolute and relative", "[svgpath]") {
    check_parse("M10 20", Path().move_to(10, 20));
    check_parse("M10 20 30 40 50 60", Path().move_to(10, 20).line_to(30, 40).line_to(50, 60));
    check_parse("m10 20 30 40 5 5", Path().move_to(10, 20).line_to(40, 60).line_to(45, 65));
    // A relative moveto after a subpath is relative to the current point.
    check_parse("M10 10 L20 20 m5 -5 1 1", Path().move_to(10, 10).line_to(20, 20).move_to(25, 15).line_to(26, 16));
    check_parse("M1 1 M2 2", Path().move_to(2, 2));  // consecutive moves: the last one wins (Path rule)
}

TEST_CASE("svg path: lineto, horizontal and vertical", "[svgpath]") {
    check_parse("M1 2 L3 4 5 6", Path().move_to(1, 2).line_to(3, 4).line_to(5, 6));
    check_parse("M1 2 l3 4 5 6", Path().move_to(1, 2).line_to(4, 6).line_to(9, 12));
    check_parse("M1 2 H5 7", Path().move_to(1, 2).line_to(5, 2).line_to(7, 2));
    check_parse("M1 2 h5 7", Path().move_to(1, 2).line_to(6, 2).line_to(13, 2));
    check_parse("M1 2 V5 7", Path().move_to(1, 2).line_to(1, 5).line_to(1, 7));
    check_parse("M1 2 v5 7", Path().move_to(1, 2).line_to(1, 7).line_to(1, 14));
}

TEST_CASE("svg path: cubic and quadratic curves", "[svgpath]") {
    check_parse("M0 0 C1 2 3 4 5 6 7 8 9 10 11 12",
                Path().move_to(0, 0).cubic_to({1, 2}, {3, 4}, {5, 6}).cubic_to({7, 8}, {9, 10}, {11, 12}));
    check_parse("M1 1 c1 2 3 4 5 6 1 1 2 2 3 3",
                Path().move_to(1, 1).cubic_to({2, 3}, {4, 5}, {6, 7}).cubic_to({7, 8}, {8, 9}, {9, 10}));
    check_parse("M0 0 Q1 2 3 4 5 6 7 8", Path().move_to(0, 0).quad_to({1, 2}, {3, 4}).quad_to({5, 6}, {7, 8}));
    check_parse("M1 1 q1 2 3 4 1 1 2 2", Path().move_to(1, 1).quad_to({2, 3}, {4, 5}).quad_to({5, 6}, {6, 7}));
}

TEST_CASE("svg path: smooth curves reflect only after the matching command", "[svgpath]") {
    // S after C: reflection of the previous second control point about the current point.
    check_parse("M0 0 C1 1 2 1 3 0 S5 -1 6 0",
                Path().move_to(0, 0).cubic_to({1, 1}, {2, 1}, {3, 0}).cubic_to({4, -1}, {5, -1}, {6, 0}));
    // S after S, and relative s.
    check_parse("M0 0 S1 1 2 0 s1 -1 2 0",
                Path().move_to(0, 0).cubic_to({0, 0}, {1, 1}, {2, 0}).cubic_to({3, -1}, {3, -1}, {4, 0}));
    // S after L, after Q, after Z: the first control point is the current point.
    check_parse("M0 0 L1 1 S2 2 3 3", Path().move_to(0, 0).line_to(1, 1).cubic_to({1, 1}, {2, 2}, {3, 3}));
    check_parse("M0 0 Q1 1 2 0 S3 1 4 0",
                Path().move_to(0, 0).quad_to({1, 1}, {2, 0}).cubic_to({2, 0}, {3, 1}, {4, 0}));
    check_parse("M0 0 C1 1 2 1 3 0 Z S1 1 2 2",
                Path().move_to(0, 0).cubic_to({1, 1}, {2, 1}, {3, 0}).close().cubic_to({0, 0}, {1, 1}, {2, 2}));
    // T after Q, T after T (reflects the previous T's computed control point), relative t.
    check_parse("M0 0 Q1 1 2 0 T4 0 t2 0",
                Path().move_to(0, 0).quad_to({1, 1}, {2, 0}).quad_to({3, -1}, {4, 0}).quad_to({5, 1}, {6, 0}));
    // T at the start and after C: control point = current point, and a following T reflects it.
    check_parse("M0 0 T2 0 4 0", Path().move_to(0, 0).quad_to({0, 0}, {2, 0}).quad_to({4, 0}, {4, 0}));
    check_parse("M0 0 C1 1 2 1 3 0 T5 0",
                Path().move_to(0, 0).cubic_to({1, 1}, {2, 1}, {3, 0}).quad_to({3, 0}, {5, 0}));
    // Q then S then T: each reflection needs its own kind.
    check_parse("M0 0 Q1 1 2 0 C3 1 4 1 5 0 T7 0",
                Path().move_to(0, 0).quad_to({1, 1}, {2, 0}).cubic_to({3, 1}, {4, 1}, {5, 0}).quad_to({5, 0}, {7, 0}));
}

TEST_CASE("svg path: arcs absolute and relative", "[svgpath]") {
    Path expected;
    expected.move_to(10, 10);
    arc_to(expected, 5, 5, 0, false, true, {20, 10});
    arc_to(expected, 5, 3, 30, true, false, {30, 20});
    check_parse("M10 10 A5 5 0 0 1 20 10 5 3 30 1 0 30 20", expected);
    check_parse("M10 10 a5 5 0 0 1 10 0 5 3 30 1 0 10 10", expected);
    // The relative arc ends exactly at current point + (dx, dy).
    const Path p = parse_svg_path("M10 10 a5 5 0 0 1 10 0");
    CHECK(p.current_point() == Point{20, 10});
    CHECK(p.points().back() == Point{20, 10});
}

TEST_CASE("svg path: closepath and relative commands after it", "[svgpath]") {
    check_parse("M10 10 L20 10 L20 20 Z", Path().move_to(10, 10).line_to(20, 10).line_to(20, 20).close());
    // After Z the current point is the subpath's start; a drawing command starts a new subpath there.
    check_parse("M10 10 l10 0 z l0 10", Path().move_to(10, 10).line_to(20, 10).close().line_to(10, 20));
    check_parse("M10 10 l10 0 z m5 5 l1 1",
                Path().move_to(10, 10).line_to(20, 10).close().move_to(15, 15).line_to(16, 16));
    check_parse("M10 10 l10 0 Zz Z h1", Path().move_to(10, 10).line_to(20, 10).close().line_to(11, 10));
    check_parse("M1 2z", Path().move_to(1, 2).close());
}

TEST_CASE("svg path: every relative command after every other command equals its absolute form", "[svgpath]") {
    // The path starts at (10, 10). Each first command ends at a known point E (after Z: the
    // subpath's start); each relative second command is written again in absolute coordinates from
    // E, and a third relative lineto checks that the current point moved to the second one's end.
    // All values are exact in binary, so the two parses must agree to the bit.
    struct First {
        const char* data;
        Point end, start;  // current point and subpath start after it
    };
    const std::vector<First> firsts = {
        {"M30 40", {30, 40}, {30, 40}},
        {"m20 30", {30, 40}, {30, 40}},
        {"L30 40", {30, 40}, {10, 10}},
        {"l20 30", {30, 40}, {10, 10}},
        {"H30", {30, 10}, {10, 10}},
        {"h20", {30, 10}, {10, 10}},
        {"V40", {10, 40}, {10, 10}},
        {"v30", {10, 40}, {10, 10}},
        {"C12 14 20 30 30 40", {30, 40}, {10, 10}},
        {"c2 4 10 20 20 30", {30, 40}, {10, 10}},
        {"S20 30 30 40", {30, 40}, {10, 10}},
        {"s10 20 20 30", {30, 40}, {10, 10}},
        {"Q20 30 30 40", {30, 40}, {10, 10}},
        {"q10 20 20 30", {30, 40}, {10, 10}},
        {"T30 40", {30, 40}, {10, 10}},
        {"t20 30", {30, 40}, {10, 10}},
        {"A10 10 0 0 1 30 40", {30, 40}, {10, 10}},
        {"a10 10 0 0 1 20 30", {30, 40}, {10, 10}},
        {"L30 40 Z", {10, 10}, {10, 10}},
        {"L30 40 z", {10, 10}, {10, 10}},
    };
    auto num = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g", v);
        return std::string(buf);
    };
    // "X p1x p1y p2x p2y ...", built with appends (GCC 12 misreports operator+ on literals here).
    auto cmd = [&](const std::string& head, std::initializer_list<Point> pts) {
        std::string out = head;
        for (const Point& q : pts) out.append(" ").append(num(q.x)).append(" ").append(num(q.y));
        return out;
    };
    for (const First& f : firsts) {
        const Point e = f.end;
        struct Second {
            std::string rel, abs;
            Point end;
        };
        const std::vector<Second> seconds = {
            {"m1.5 2", cmd("M", {e + Vec{1.5, 2}}), e + Vec{1.5, 2}},
            {"l1.5 2", cmd("L", {e + Vec{1.5, 2}}), e + Vec{1.5, 2}},
            {"h1.5", cmd("H", {}).append(num(e.x + 1.5)), e + Vec{1.5, 0}},
            {"v2", cmd("V", {}).append(num(e.y + 2)), e + Vec{0, 2}},
            {"c1 1 2 2.5 3 3", cmd("C", {e + Vec{1, 1}, e + Vec{2, 2.5}, e + Vec{3, 3}}), e + Vec{3, 3}},
            {"s2 2.5 3 3", cmd("S", {e + Vec{2, 2.5}, e + Vec{3, 3}}), e + Vec{3, 3}},
            {"q1 2.5 3 3", cmd("Q", {e + Vec{1, 2.5}, e + Vec{3, 3}}), e + Vec{3, 3}},
            {"t3 3", cmd("T", {e + Vec{3, 3}}), e + Vec{3, 3}},
            {"a4 4 0 0 1 3 3", cmd("A4 4 0 0 1", {e + Vec{3, 3}}), e + Vec{3, 3}},
            {"z", "Z", f.start},
        };
        for (const Second& s2 : seconds) {
            const Point third = s2.end + Vec{1, 1};
            std::string rel = "M10 10 ", abs = "M10 10 ";
            rel.append(f.data).append(" ").append(s2.rel).append(" l1 1");
            abs.append(f.data).append(" ").append(s2.abs).append(" ").append(cmd("L", {third}));
            INFO(rel << "  vs  " << abs);
            const Path a = parse_svg_path(rel), b = parse_svg_path(abs);
            CHECK(dump(a) == dump(b));
            CHECK(a.current_point() == third);
        }
    }
}

TEST_CASE("svg path: empty and whitespace-only data give an empty path", "[svgpath]") {
    CHECK(parse_svg_path("").empty());
    CHECK(parse_svg_path(" \t\r\n\f").empty());
    std::string err = "stale";
    CHECK(parse_svg_path_lenient("  ", &err).empty());
    CHECK(err.empty());
}

// ---------------------------------------------------------------------------------------------
// Numbers and separators

TEST_CASE("svg path: number syntax", "[svgpath]") {
    check_parse("M1e-3 1E+5", Path().move_to(1e-3, 1e5));
    check_parse("M.5.5", Path().move_to(0.5, 0.5));
    check_parse("M-1-2", Path().move_to(-1, -2));
    check_parse("M+3+4", Path().move_to(3, 4));
    check_parse("M1.+2.", Path().move_to(1, 2));
    check_parse("M1.e2 2.5E-1", Path().move_to(100, 0.25));
    check_parse("M1e2.5", Path().move_to(100, 0.5));  // the exponent ends at '.'
    check_parse("M-.5-.5", Path().move_to(-0.5, -0.5));
    check_parse("M000012 0.000", Path().move_to(12, 0));
    check_parse("M0.1 0.2", Path().move_to(0.1, 0.2));  // correctly rounded, as std::from_chars
    check_parse("M3.14159265358979323846264338327950288 1", Path().move_to(kPi, 1));
    check_parse("M1.5.5.5.5", Path().move_to(1.5, 0.5).line_to(0.5, 0.5));
    // Underflow reads as zero (with its sign).
    const Path u = parse_svg_path("M1e-400 -1e-99999999999999999999");
    CHECK(u.points()[0].x == 0);
    CHECK(std::signbit(u.points()[0].y));
    // Subnormals survive.
    CHECK(parse_svg_path("M4.9406564584124654e-324 0").points()[0].x == std::numeric_limits<double>::denorm_min());
    CHECK(parse_svg_path("M1.7976931348623157e308 0").points()[0].x == std::numeric_limits<double>::max());
}

TEST_CASE("svg path: comma and whitespace rules", "[svgpath]") {
    const Path expected = Path().move_to(1, 2).line_to(3, 4);
    check_parse("M1,2,3,4", expected);
    check_parse("M1 ,2 , 3, 4", expected);
    check_parse("  M 1\t2\n3\r\n4\f ", expected);
    check_parse("M1,2L3,4", expected);
    check_parse("M1,2 L 3 4", expected);
    CHECK(parse_error("M1,,2") == "path data column 4: expected a number for y of 'M', found ','");
    CHECK(parse_error("M,1 2") == "path data column 2: expected a number after 'M', found ','");
    CHECK(parse_error("M1 2,") == "path data column 6: expected a number after ',', found end of data");
    CHECK(parse_error("M1 2, L3 4") == "path data column 7: expected a number after ',', found 'L'");
    // A comma may also separate argument groups of a repeated command.
    check_parse("M1 2 L3 4 ,5 6", Path().move_to(1, 2).line_to(3, 4).line_to(5, 6));
    CHECK(parse_error("M1 2 L3 4 ,,5 6") == "path data column 12: expected a number after ',', found ','");
}

TEST_CASE("svg path: malformed and out-of-range numbers", "[svgpath]") {
    CHECK(parse_error("M10e 5") == "path data column 5: expected a digit after 'e', found ' '");
    CHECK(parse_error("M0 10e") == "path data column 7: expected a digit after 'e', found end of data");
    CHECK(parse_error("M0.5e 1") == "path data column 6: expected a digit after 'e', found ' '");
    CHECK(parse_error("M1e+ 2") == "path data column 5: expected a digit after '+', found ' '");
    CHECK(parse_error("M- 1 2") == "path data column 3: expected a digit after '-', found ' '");
    CHECK(parse_error("M. 1 2") == "path data column 3: expected a digit after '.', found ' '");
    CHECK(parse_error("M-.e1 2") == "path data column 4: expected a digit after '.', found 'e'");
    CHECK(parse_error("M+-1 2") == "path data column 3: expected a digit after '+', found '-'");
    CHECK(parse_error("M1e400 0") == "path data column 2: number out of range");
    CHECK(parse_error("M0 0 L1 -1e99999999999999999999") == "path data column 9: number out of range");
    CHECK(parse_error("M0 0 L1 0.00001e320") == "path data column 9: number out of range");
    CHECK(parse_svg_path("M0 0 L1 0.00001e310").points()[1].y == 1e305);
    // A relative coordinate or a reflection that overflows is out of range too.
    CHECK(parse_error("M1e308 0 l1e308 0") == "path data column 11: number out of range");
    CHECK(parse_error("M0 0 Q-1.7e308 0 1.7e308 0 T 0 0") == "path data column 30: number out of range");
    // NaN and infinity are not numbers in path data.
    CHECK(parse_error("M0 0 L nan 1") == "path data column 8: expected a number after 'L', found 'n'");
    CHECK(parse_error("M0 0 L inf 1") == "path data column 8: expected a number after 'L', found 'i'");
}

TEST_CASE("svg path: arc flags without separators", "[svgpath]") {
    Path a;
    a.move_to(0, 0);
    arc_to(a, 1, 1, 0, false, false, {1, 1});
    check_parse("M0 0 a1 1 0 00 1 1", a);
    check_parse("M0 0 a1 1 0 0 0 1 1", a);
    check_parse("M0 0 a1,1,0,0,0,1,1", a);
    Path b;
    b.move_to(0, 0);
    arc_to(b, 1, 1, 0, true, true, {10, 10});
    check_parse("M0 0 a1,1,0,1,1,10,10", b);
    check_parse("M0 0 a1 1 0 1110 10", b);  // flags 1 1, then x = 10
    check_parse("M0 0 A1 1 0 11 10 10", b);
    Path c;
    c.move_to(0, 0);
    arc_to(c, 4, 2, -30, false, true, {0.5, 0.25});
    check_parse("M0 0 a4 2-30 01.5.25", c);  // flags 0 1, x = .5, y = .25
    // Flags must be the single characters 0 or 1.
    CHECK(parse_error("M0 0 a1 1 0 2 1 1 1") ==
          "path data column 13: expected a flag (0 or 1) for large-arc-flag of 'a', found '2'");
    CHECK(parse_error("M0 0 A1 1 0 0 .5 1 1") ==
          "path data column 15: expected a flag (0 or 1) for sweep-flag of 'A', found '.'");
    CHECK(parse_error("M0 0 A1 1 0 0 -1 1 1") ==
          "path data column 15: expected a flag (0 or 1) for sweep-flag of 'A', found '-'");
    CHECK(parse_error("M0 0 A1 1 0 1") ==
          "path data column 14: expected a flag (0 or 1) for sweep-flag of 'A', found end of data");
    // Negative radii are taken as their absolute values.
    check_parse("M0 0 a-1 -1 0 00 1 1", a);
}

// ---------------------------------------------------------------------------------------------
// Errors and the lenient parser

TEST_CASE("svg path: errors carry the column, what was expected and what was found", "[svgpath]") {
    CHECK(parse_error("L1 2") == "path data column 1: expected 'M' or 'm' at the start of path data, found 'L'");
    CHECK(parse_error("  x") == "path data column 3: expected 'M' or 'm' at the start of path data, found 'x'");
    CHECK(parse_error("1 2") == "path data column 1: expected 'M' or 'm' at the start of path data, found '1'");
    CHECK(parse_error("M") == "path data column 2: expected a number after 'M', found end of data");
    CHECK(parse_error("M1 2 L") == "path data column 7: expected a number after 'L', found end of data");
    CHECK(parse_error("M1 2 L3") == "path data column 8: expected a number for y of 'L', found end of data");
    CHECK(parse_error("M1 2 C1 2 3 4 5") == "path data column 16: expected a number for y of 'C', found end of data");
    CHECK(parse_error("M1 2 C1 2 3 x") == "path data column 13: expected a number for y2 of 'C', found 'x'");
    CHECK(parse_error("M1 2 x") == "path data column 6: expected a number or a command letter, found 'x'");
    CHECK(parse_error("M1 2 Z 3") == "path data column 8: expected a command letter after 'Z', found '3'");
    CHECK(parse_error("M1 2 L3 4 5") == "path data column 12: expected a number for y of 'L', found end of data");
    // Columns count characters, not bytes; non-ASCII is named by its code point.
    CHECK(parse_error("M0 0 \xC3\xA9 L") == "path data column 6: expected a number or a command letter, found U+00E9");
    CHECK(parse_error("M0 0 L\xC3\xA9\xC3\xA9 x") == "path data column 7: expected a number after 'L', found U+00E9");
    CHECK(parse_error("M0 0 L\xFF") == "path data column 7: expected a number after 'L', found byte 0xFF");
    CHECK(parse_error("M0 0 L\t") == "path data column 8: expected a number after 'L', found end of data");
    CHECK(parse_error(std::string("M0 0 L\x01", 7).c_str()) ==
          "path data column 7: expected a number after 'L', found U+0001");
}

TEST_CASE("svg path: lenient parsing keeps the complete segments before the error", "[svgpath]") {
    std::string err;
    Path p = parse_svg_path_lenient("M10 10 L20 20 L30", &err);
    CHECK(p == Path().move_to(10, 10).line_to(20, 20));
    CHECK(err == "path data column 18: expected a number for y of 'L', found end of data");
    // In the middle of an implicit repetition.
    p = parse_svg_path_lenient("M0 0 L1 1 2 2 3 x", &err);
    CHECK(p == Path().move_to(0, 0).line_to(1, 1).line_to(2, 2));
    CHECK(err == "path data column 17: expected a number for y of 'L', found 'x'");
    // An incomplete curve is dropped entirely.
    p = parse_svg_path_lenient("M0 0 L5 5 C1 1 2 2", &err);
    CHECK(p == Path().move_to(0, 0).line_to(5, 5));
    p = parse_svg_path_lenient("M1 2 L3 4 Z 5", &err);
    CHECK(p == Path().move_to(1, 2).line_to(3, 4).close());
    p = parse_svg_path_lenient("M1 2 L1e999 4", &err);
    CHECK(p == Path().move_to(1, 2));
    CHECK(err == "path data column 7: number out of range");
    p = parse_svg_path_lenient("L1 2", &err);
    CHECK(p.empty());
    CHECK(!err.empty());
    p = parse_svg_path_lenient("M1 2 L3 4", &err);
    CHECK(p == Path().move_to(1, 2).line_to(3, 4));
    CHECK(err.empty());
    // Without an error string it just returns the prefix.
    CHECK(parse_svg_path_lenient("M1 2 L3 4 L") == Path().move_to(1, 2).line_to(3, 4));
}

TEST_CASE("svg path: point limit and options", "[svgpath]") {
    SvgPathOptions o;
    o.max_points = 4;
    CHECK(parse_svg_path("M0 0 L1 1 2 2 3 3", o).points().size() == 4);
    try {
        (void)parse_svg_path("M0 0 L1 1 2 2 3 3 4 4", o);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Limit);
        CHECK(std::string(e.what()) == "path data column 19: path data holds more than 4 points");
    }
    // A cubic needs 3 points; a segment after Z also needs its implicit move.
    CHECK_THROWS_AS(parse_svg_path("M0 0 L1 1 C1 1 2 2 3 3", o), Error);
    CHECK_THROWS_AS(parse_svg_path("M0 0 L1 1 2 2 Z L3 3", o), Error);
    CHECK(parse_svg_path("M0 0 L1 1 2 2 M 3 3", o).points().size() == 4);
    std::string err;
    const Path p = parse_svg_path_lenient("M0 0 L1 1 2 2 3 3 4 4", &err, o);
    CHECK(p.points().size() == 4);
    CHECK(err == "path data column 19: path data holds more than 4 points");
    // The limit can only be lowered.
    o.max_points = std::numeric_limits<std::size_t>::max();
    CHECK(parse_svg_path("M0 0 L1 1", o).points().size() == 2);

    SvgPathOptions bad;
    bad.arc_tolerance = 0;
    CHECK_THROWS_AS(parse_svg_path("M0 0", bad), Error);
    bad.arc_tolerance = std::nan("");
    CHECK_THROWS_AS(parse_svg_path_lenient("M0 0", nullptr, bad), Error);
}

// ---------------------------------------------------------------------------------------------
// Formatting and round trips

TEST_CASE("svg path: format writes compact absolute data", "[svgpath]") {
    CHECK(format_svg_path(Path()).empty());
    CHECK(format_svg_path(parse_svg_path("m0 0 h10 v10 h-5 v-5 z")) == "M0 0H10V10H5V5Z");
    CHECK(format_svg_path(parse_svg_path("M1000 0.001 L1e21 -0.5 123456 1e-7")) == "M1e3 .001 1e21-.5 123456 1e-7");
    CHECK(format_svg_path(parse_svg_path("M0.5 0.25 L-0.5 -0.25 1.5 2")) == "M.5.25-.5-.25 1.5 2");
    CHECK(format_svg_path(parse_svg_path("M0 0 C1 1 2 1 3 0 S5 -1 6 0 C 1 2 3 4 5 6")) ==
          "M0 0C1 1 2 1 3 0S5-1 6 0C1 2 3 4 5 6");
    CHECK(format_svg_path(parse_svg_path("M0 0 Q1 1 2 0 T4 0 T6 0 L7 7")) == "M0 0Q1 1 2 0T4 0 6 0L7 7");
    CHECK(format_svg_path(parse_svg_path("M1 1 L5 5 z l1 0")) == "M1 1 5 5ZM1 1H2");
    CHECK(format_svg_path(Path().move_to(0.1 + 0.2, 0.0)) == "M.30000000000000004 0");
    CHECK(format_svg_path(Path().move_to(-0.0, 1).line_to(0.0, 2).line_to(1, -0.0)) == "M-0 1 0 2 1-0");
    CHECK(format_svg_path(Path().line_to(1, 2)) == "M0 0 1 2");
    CHECK(format_svg_path(Path().move_to(1, 2).line_to(3, 4).move_to(5, 6)) == "M1 2 3 4M5 6");
    Path bad;
    bad.move_to(std::nan(""), 0);
    CHECK_THROWS_AS(format_svg_path(bad), Error);
}

TEST_CASE("svg path: format then parse gives the same path (fixed set)", "[svgpath]") {
    const char* inputs[] = {
        "M10 20 30 40 50 60",
        "m1 1 2 2 l3 3 h4 v5 z m1 1 2 2 Z",
        "M0 0 C1 1 2 1 3 0 S5 -1 6 0 s1 1 2 2 Q1 2 3 4 T5 6 t1 1 Z",
        "M0 0 a25 25 -30 0 1 50 -25 a25 50 -30 1 0 50 -25 Z",
        "M.1.2.3.4-.5-.6 1e-300 1e300 -1.7976931348623157e308 4.9406564584124654e-324",
        "M1 2 L3 4 M5 6",
        "M1 2 Z Z L3 4 Z",
        "M3 3 C3 3 3 3 3 3 S3 3 3 3 Q3 3 3 3 T3 3",
        "M0 0 A 1 1 0 1 1 0 0.0001",
        "M100 100 h1e-17 v-1e-17 l0.1 0.2 0.30000000000000004 0.7",
    };
    for (const char* d : inputs) {
        INFO(d);
        const Path p = parse_svg_path(d);
        const std::string f = format_svg_path(p);
        INFO(f);
        const Path q = parse_svg_path(f);
        CHECK(dump(q) == dump(p));
        CHECK(q == p);
        CHECK(format_svg_path(q) == f);
    }
}

TEST_CASE("svg path: format then parse gives the same path (random paths)", "[svgpath]") {
    std::mt19937_64 rng(20240611);
    auto coord = [&]() -> double {
        switch (rng() % 7) {
            case 0: return static_cast<double>(static_cast<int>(rng() % 201) - 100);
            case 1: return std::uniform_real_distribution<double>(-1000, 1000)(rng);
            case 2: {
                const double m = std::uniform_real_distribution<double>(1, 10)(rng);
                const int e = static_cast<int>(rng() % 601) - 300;
                return (rng() & 1 ? -1 : 1) * m * std::pow(10.0, e);
            }
            case 3: {
                // Any finite double, subnormals included.
                while (true) {
                    const std::uint64_t bits = rng();
                    double v;
                    std::memcpy(&v, &bits, sizeof v);
                    if (std::isfinite(v)) return v;
                }
            }
            case 4: return rng() & 1 ? 0.0 : -0.0;
            case 5: return static_cast<double>(static_cast<int>(rng() % 1001) - 500) / 8;
            default: return static_cast<double>(static_cast<int>(rng() % 2001) - 1000) / 10;  // 0.1 steps
        }
    };
    for (int iter = 0; iter < 2000; ++iter) {
        Path p;
        const int n = 1 + static_cast<int>(rng() % 20);
        Point last_cubic{}, last_quad{};
        for (int k = 0; k < n; ++k) {
            const Point cur = p.current_point();
            switch (rng() % 10) {
                case 0: p.move_to({coord(), coord()}); break;
                case 1: p.line_to({coord(), coord()}); break;
                case 2: p.line_to({coord(), cur.y}); break;  // horizontal
                case 3: p.line_to({cur.x, coord()}); break;  // vertical
                case 4:
                    last_quad = {coord(), coord()};
                    p.quad_to(last_quad, {coord(), coord()});
                    break;
                case 5:
                    last_cubic = {coord(), coord()};
                    p.cubic_to({coord(), coord()}, last_cubic, {coord(), coord()});
                    break;
                case 6: {  // a smooth cubic (reflected first control point), when representable
                    const Point c1{2 * cur.x - last_cubic.x, 2 * cur.y - last_cubic.y};
                    last_cubic = {coord(), coord()};
                    if (c1.is_finite()) p.cubic_to(c1, last_cubic, {coord(), coord()});
                    break;
                }
                case 7: {
                    const Point c{2 * cur.x - last_quad.x, 2 * cur.y - last_quad.y};
                    if (c.is_finite()) {
                        p.quad_to(c, {coord(), coord()});
                        last_quad = c;
                    }
                    break;
                }
                case 8: p.close(); break;
                default: p.cubic_to(cur, {coord(), coord()}, {coord(), coord()}); break;
            }
        }
        const std::string f = format_svg_path(p);
        INFO("iteration " << iter << ": " << f);
        const Path q = parse_svg_path(f);
        REQUIRE(dump(q) == dump(p));
        REQUIRE(q == p);
    }
}

TEST_CASE("svg path: conics are written as cubics within 1e-9 relative", "[svgpath]") {
    struct Case {
        Point p0, p1, p2;
        double w;
    };
    const double h = std::sqrt(0.5);
    const Case cases[] = {
        {{100, 0}, {100, 100}, {0, 100}, h},                  // quarter circle of radius 100
        {{0, 0}, {50, 80}, {100, 0}, 0.2},                    // an ellipse arc
        {{0, 0}, {50, 80}, {100, 0}, 1.0},                    // a parabola
        {{0, 0}, {50, 80}, {100, 0}, 3.0},                    // a hyperbola
        {{0, 0}, {50, 80}, {100, 0}, 50.0},                   // nearly the control polygon
        {{1e6, 1e6}, {1e6 + 3, 1e6}, {1e6 + 3, 1e6 + 3}, h},  // small, far from the origin
    };
    for (const Case& c : cases) {
        INFO("w = " << c.w);
        Path p;
        p.move_to(c.p0);
        p.conic_to(c.p1, c.p2, c.w);
        const std::string f = format_svg_path(p);
        const Path q = parse_svg_path(f);
        REQUIRE(q.verbs()[0] == Verb::Move);
        CHECK(q.points()[0] == c.p0);
        CHECK(q.points().back() == c.p2);
        const double size = std::max({distance(c.p0, c.p1), distance(c.p1, c.p2), distance(c.p0, c.p2)});
        // Reference: the conic densely sampled, each nearest sample refined by ternary search.
        auto conic = [&](double t) {
            const double mt = 1 - t, b0 = mt * mt, b1 = 2 * c.w * mt * t, b2 = t * t;
            return (c.p0 * b0 + c.p1 * b1 + c.p2 * b2) / (b0 + b1 + b2);
        };
        constexpr int kRef = 1000;
        std::vector<Point> ref(kRef + 1);
        for (int i = 0; i <= kRef; ++i) ref[static_cast<std::size_t>(i)] = conic(static_cast<double>(i) / kRef);
        double worst = 0;
        Point cur = c.p0;
        std::size_t pi = 1;
        for (std::size_t vi = 1; vi < q.verbs().size(); ++vi) {
            REQUIRE(q.verbs()[vi] == Verb::Cubic);
            const Point c1 = q.points()[pi], c2 = q.points()[pi + 1], e = q.points()[pi + 2];
            pi += 3;
            for (int j = 0; j <= 40; ++j) {
                const Point s = cubic_at(cur, c1, c2, e, j / 40.0);
                std::size_t best = 0;
                for (std::size_t i = 1; i < ref.size(); ++i)
                    if (distance(ref[i], s) < distance(ref[best], s)) best = i;
                double lo = std::max(0.0, (static_cast<double>(best) - 1) / kRef);
                double hi = std::min(1.0, (static_cast<double>(best) + 1) / kRef);
                for (int it = 0; it < 100; ++it) {
                    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
                    if (distance(conic(m1), s) < distance(conic(m2), s))
                        hi = m2;
                    else
                        lo = m1;
                }
                worst = std::max(worst, distance(conic((lo + hi) / 2), s));
            }
            cur = e;
        }
        CHECK(worst <= 1e-9 * size);
        CHECK(q.verbs().size() - 1 <= 64);  // and not absurdly many pieces
    }
}

// ---------------------------------------------------------------------------------------------
// Points lists

TEST_CASE("svg path: points lists for polyline and polygon", "[svgpath]") {
    CHECK(parse_points("10,20 30,40 50 60") == Path().move_to(10, 20).line_to(30, 40).line_to(50, 60));
    CHECK(parse_points("10,20 30,40 50 60", true) == Path().move_to(10, 20).line_to(30, 40).line_to(50, 60).close());
    CHECK(parse_points(" 1-2-3-4 ") == Path().move_to(1, -2).line_to(-3, -4));
    CHECK(parse_points(".5.5,1e1 , 2") == Path().move_to(0.5, 0.5).line_to(10, 2));
    CHECK(parse_points("").empty());
    CHECK(parse_points(" \n", true).empty());
    CHECK(parse_points("3 4", true) == Path().move_to(3, 4).close());
    auto error = [](const char* s) -> std::string {
        try {
            (void)parse_points(s);
        } catch (const Error& e) {
            CHECK(e.kind() == ErrorKind::Parse);
            return e.what();
        }
        return "(no error)";
    };
    CHECK(error("10,20 30,40 50") == "points column 15: expected a number (y of point 3), found end of data");
    CHECK(error("10,20,") == "points column 7: expected a number after ',', found end of data");
    CHECK(error("10,,20") == "points column 4: expected a number (y of point 1), found ','");
    CHECK(error("10 20 x") == "points column 7: expected a number (x of point 2), found 'x'");
    CHECK(error("1e 2") == "points column 3: expected a digit after 'e', found ' '");
    CHECK(error("1 1e500") == "points column 3: number out of range");
    std::string err;
    CHECK(parse_points_lenient("1 2 3 4 5", true, &err) == Path().move_to(1, 2).line_to(3, 4).close());
    CHECK(err == "points column 10: expected a number (y of point 3), found end of data");
    CHECK(parse_points_lenient("1 2 3 4", false, &err) == Path().move_to(1, 2).line_to(3, 4));
    CHECK(err.empty());
}
