// Helpers shared by the SVG path data and SVG arc tests (test_svg_path.cpp, test_arc.cpp): an exact
// listing of a Path, a parse checked against the expected Path, the message of a parse error, and
// a point of a cubic Bezier.
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdio>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/path.hpp"
#include "casteljau/svg_path.hpp"

namespace svg_path_test {

using casteljau::Error;
using casteljau::ErrorKind;
using casteljau::parse_svg_path;
using casteljau::Path;
using casteljau::Point;
using casteljau::Verb;
using casteljau::verb_point_count;

// A readable, exact listing of a Path (verbs and points with 17 significant digits).
inline std::string dump(const Path& p) {
    std::string s;
    std::size_t pi = 0, wi = 0;
    char buf[64];
    for (Verb v : p.verbs()) {
        switch (v) {
            case Verb::Move: s += "M"; break;
            case Verb::Line: s += "L"; break;
            case Verb::Quad: s += "Q"; break;
            case Verb::Cubic: s += "C"; break;
            case Verb::Conic: s += "K"; break;
            case Verb::Close: s += "Z"; break;
        }
        for (int k = 0; k < verb_point_count(v); ++k, ++pi) {
            std::snprintf(buf, sizeof buf, " %.17g,%.17g", p.points()[pi].x, p.points()[pi].y);
            s += buf;
        }
        if (v == Verb::Conic) {
            std::snprintf(buf, sizeof buf, " w=%.17g", p.weights()[wi++]);
            s += buf;
        }
        s += "; ";
    }
    return s;
}

inline void check_parse(const char* d, const Path& expected) {
    INFO("path data: " << d);
    const Path got = parse_svg_path(d);
    CHECK(dump(got) == dump(expected));
    CHECK(got == expected);
}

inline std::string parse_error(const char* d) {
    try {
        (void)parse_svg_path(d);
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Parse);
        return e.what();
    }
    return "(no error)";
}

inline Point cubic_at(Point p0, Point p1, Point p2, Point p3, double t) {
    const double mt = 1 - t;
    return p0 * (mt * mt * mt) + p1 * (3 * mt * mt * t) + p2 * (3 * mt * t * t) + p3 * (t * t * t);
}

}  // namespace svg_path_test
