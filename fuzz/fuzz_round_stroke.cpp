// libFuzzer target: round_stroke_mask (casteljau/round_stroke.hpp) against the exact union of the
// same strokes, on small random polylines.
//
// Input: byte 0 picks the radius (0.02 to 10 px) and byte 1 the sample lines per pixel (8 to 64);
// the rest is polylines, one byte per coordinate (x, y in [0, 32) px in steps of 1/8), a byte 255
// ending a polyline (a polyline of one point is a disc). Checks, each aborting on failure:
//   1. every pixel is within the documented bound of the exact union's coverage (stroke() with
//      round joins and caps at a tolerance of 1e-3 px, filled exactly by the rasterizer): 1/(2
//      lines) times the horizontal extent of the union's boundary inside the pixel, which is at
//      most 6 px per capsule reaching the pixel (two sides of at most 1, two half circles of at
//      most 2), plus 2/255 for the two roundings and the reference's arcs;
//   2. a clip cutting the image in two horizontal bands gives the same pixels as the whole.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/round_stroke.hpp"
#include "casteljau/stroke.hpp"

namespace {

using namespace casteljau;

constexpr int kSize = 48;

[[noreturn]] void fail(const char* what, int x, int y, double a, double b) {
    std::fprintf(stderr, "fuzz_round_stroke: %s at pixel (%d, %d): %g vs %g\n", what, x, y, a, b);
    std::abort();
}

// How many capsules (segments grown by r) reach each pixel of the image.
std::vector<int> capsules_per_pixel(const std::vector<LineSegment>& segs, double r) {
    std::vector<int> n(kSize * kSize, 0);
    for (const LineSegment& s : segs) {
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min(s.a.x, s.b.x) - r)));
        const int x1 = std::min(kSize - 1, static_cast<int>(std::floor(std::max(s.a.x, s.b.x) + r)));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min(s.a.y, s.b.y) - r)));
        const int y1 = std::min(kSize - 1, static_cast<int>(std::floor(std::max(s.a.y, s.b.y) + r)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) ++n[static_cast<std::size_t>(y * kSize + x)];
    }
    return n;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 4 || size > 512) return 0;
    const double r = 0.02 + 10.0 * (data[0] / 255.0) * (data[0] / 255.0);
    const int lines = 8 + data[1] % 57;
    Path path;
    std::vector<LineSegment> segs;
    std::vector<Point> line;
    auto end_line = [&] {
        if (line.empty()) return;
        path.move_to(line[0]);
        if (line.size() == 1) {
            path.line_to(line[0]);  // a lone point strokes as a disc with round caps
            segs.push_back({line[0], line[0]});
        }
        for (std::size_t i = 1; i < line.size(); ++i) {
            path.line_to(line[i]);
            segs.push_back({line[i - 1], line[i]});
        }
        line.clear();
    };
    for (std::size_t i = 2; i < size;) {
        if (data[i] == 255) {
            end_line();
            ++i;
            continue;
        }
        if (i + 1 >= size) break;
        line.push_back({8 + data[i] / 8.0, 8 + data[i + 1] / 8.0});
        i += 2;
    }
    end_line();
    if (segs.empty()) return 0;
    const IRect all{0, 0, kSize, kSize};
    const Mask m = round_stroke_mask(segs, r, all, lines);
    StrokeStyle st;
    st.width = 2 * r;
    st.join = LineJoin::Round;
    st.cap = LineCap::Round;
    Rasterizer rast;
    Mask truth;
    try {
        truth = rast.fill_mask(stroke(path, st, Affine{}, 1e-3), Affine{}, FillOptions{}, all);
    } catch (const Error&) {
        return 0;  // the reference outline exceeds a limit: nothing to compare
    }
    if (rast.last_stats().dense_cells > 0) return 0;  // the reference itself is approximate there
    const std::vector<int> caps = capsules_per_pixel(segs, r);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double bound = 255.0 * 6 * caps[static_cast<std::size_t>(y * kSize + x)] / (2.0 * lines) + 2;
            if (std::abs(m.at(x, y) - truth.at(x, y)) > bound)
                fail("beyond the bound", x, y, m.at(x, y), truth.at(x, y));
        }
    const int cut = 1 + data[size - 1] % (kSize - 1);
    for (const IRect& band : {IRect{0, 0, kSize, cut}, IRect{0, cut, kSize, kSize}}) {
        const Mask part = round_stroke_mask(segs, r, band, lines);
        for (int y = band.y0; y < band.y1; ++y)
            for (int x = 0; x < kSize; ++x)
                if (part.at(x, y) != m.at(x, y)) fail("a band differs from the whole", x, y, part.at(x, y), m.at(x, y));
    }
    return 0;
}
