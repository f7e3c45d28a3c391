// Random paths for the geometry fuzz targets (rasterizer, stroker): verbs and coordinates from
// the fuzzer's bytes, with hostile values (NaN, infinities, 1e30, denormals, zero-length
// segments, repeated points, points of a coarse lattice) as often as ordinary ones, and sometimes
// long runs of segments.
#pragma once

#include "casteljau/path.hpp"
#include "harness.hpp"

namespace casteljau::fuzz {

inline Path random_path(Bytes& in, double span) {
    Path p;
    Point last{0, 0};
    auto point = [&] {
        const std::uint8_t how = in.byte();
        if (how % 8 == 0) return last;                                                           // zero-length piece
        if (how % 8 == 1) return Point{last.x + in.number(4) / 64, last.y + in.number(4) / 64};  // tiny step
        if (how % 8 == 2) {  // a node of a 5 x 5 lattice: contours touch, fold back and share edges
            const double ix = in.byte() % 5, iy = in.byte() % 5;
            return Point{span / 4 * ix, span / 4 * iy};
        }
        return Point{in.number(span), in.number(span)};
    };
    auto piece = [&](std::uint8_t verb) {
        switch (verb % 8) {
            case 0: p.move_to(last = point()); break;
            case 1:
            case 2: p.line_to(last = point()); break;
            case 3: {
                const Point c = point();
                p.quad_to(c, last = point());
                break;
            }
            case 4: {
                const Point c1 = point(), c2 = point();
                p.cubic_to(c1, c2, last = point());
                break;
            }
            case 5: {
                const Point c = point();
                p.conic_to(c, last = point(), in.number(4));
                break;
            }
            case 6: p.close(); break;
            default: {  // a run of many short segments
                const int n = in.range(1, 2000);
                const double dx = in.number(2), dy = in.number(2);
                for (int k = 0; k < n; ++k) p.line_to(last = Point{last.x + dx * ((k & 1) ? 1 : -0.5), last.y + dy});
            }
        }
    };
    const int verbs = in.range(0, 64);
    for (int i = 0; i < verbs && !in.empty(); ++i) {
        const std::uint8_t verb = in.byte();
        run([&] { piece(verb); });  // a piece the Path refuses (a bad conic weight) is left out
    }
    return p;
}

}  // namespace casteljau::fuzz
