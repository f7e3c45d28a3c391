// libFuzzer target: differential test of the rasterizer's fast path (topology decided before
// rasterizing, src/raster/topology.cpp) against the exact references, on small random paths.
//
// Input: byte 0 picks the fill rule (bit 0), a transform (bits 1-3) and the rasterizer's mode; the
// rest is a program of commands, one byte each followed by its coordinates (one byte per
// coordinate, mapped to [0, 32) px in steps of 1/8):
//   0 move, 1 line, 2 quad, 3 cubic, 4 close, 5 stacked copy of everything so far (offset by the
//   next two bytes in 1/64 px, often 0: an exact copy), 6 conic (weight from the next byte).
// Checks, each aborting on failure:
//   1. default options (exact, topology decided per fill: the winding sweep for a shape not
//      proven simple) against the exact cells (every shape through the per-cell overlap check,
//      winding sweep off): the same flattening, so they must agree to rounding, |difference| <=
//      1/255 at every pixel;
//   2. for straight-edged paths, default options against the independent exact-area reference of
//      tests/support/reference_area.* (slab integration): within 1/255 at every pixel;
//   3. a path classify_topology proves Simple renders through the fast path (that verdict given
//      in FillOptions::topology) and with plain accumulation within 1/255 of the exact cells;
//   4. under the similarity maps, at a flattening tolerance from 0.015 to 2 px (bits 4-5 of byte
//      0), a path that classify_topology(path, tolerance / scale) proves Simple renders by plain
//      accumulation within 1/255 of the exact cells at that tolerance;
//   5. with FillOptions::hidden (a pattern of pixels picked by bits 6-7 of byte 0), every hidden
//      pixel within 1/255 of plain accumulation and every other one equal to the exact cells;
//   6. a path proven Simple as in 3, with a far square beside it so that its box is too wide for
//      the row vectors (the float cells accumulate it): plain accumulation within 1/255 of the
//      exact cells;
//   7. every path through the winding sweep (topology given as Overlapping), alone and with the
//      far square of 6: within 1/255 of the exact cells;
//   8. for straight-edged paths, the overlap check confined to find_overlap_region's boxes (found
//      on the untransformed path, mapped by the transform; plain accumulation for a path it
//      proves Simple): within 1/255 of the exact cells;
//   9. the exact cells with a far square that makes the overlap check take bands of 27 rows
//      across the path: within 1/255 of the exact cells in one dense buffer.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/raster.hpp"
#include "../tests/support/reference_area.hpp"

namespace {

using namespace casteljau;

constexpr int kSize = 40;

struct Reader {
    const std::uint8_t* p;
    std::size_t n, i = 0;
    bool more() const { return i < n; }
    std::uint8_t byte() { return i < n ? p[i++] : 0; }
    double coord() { return byte() / 8.0; }
    Point point() {
        const double x = coord();
        return {x, coord()};
    }
};

// The path mapped by m, with a 1 x 1 square at x = far: at 600 a box too wide for the row
// vectors, so plain accumulation takes the float cells; at 1200 a box of more cells than the
// overlap check takes in one dense buffer, so it takes bands of 27 rows.
Path with_far_square(const Path& path, const Affine& m, double far = 600) {
    Path wide;
    wide.append(path, m);
    wide.move_to({far, 0});
    wide.line_to({far + 1, 0});
    wide.line_to({far + 1, 1});
    wide.line_to({far, 1});
    wide.close();
    return wide;
}

Mask render(Rasterizer& r, const Path& p, const Affine& m, const FillOptions& o) {
    return r.fill_mask(p, m, o, IRect{0, 0, kSize, kSize});
}

[[noreturn]] void fail(const char* what, int x, int y, int a, int b) {
    std::fprintf(stderr, "fuzz_raster_diff: %s at pixel (%d, %d): %d vs %d\n", what, x, y, a, b);
    std::abort();
}

void expect_close(const char* what, const Mask& a, const Mask& b) {
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            if (std::abs(a.at(x, y) - b.at(x, y)) > 1) fail(what, x, y, a.at(x, y), b.at(x, y));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2 || size > 4096) return 0;
    Reader in{data, size};
    const std::uint8_t head = in.byte();
    FillOptions opts;
    opts.rule = (head & 1) ? FillRule::EvenOdd : FillRule::NonZero;
    static const Affine kMaps[] = {Affine{},
                                   Affine::scale(-1, 1) * Affine::translate(-36, 0),
                                   Affine::scale(0.5, 0.75),
                                   Affine{0.8, 0.3, -0.25, 0.9, 6, 1},
                                   Affine::scale(1.0 / 3.0, 3.0),
                                   Affine::translate(0.37, -0.61),
                                   Affine::rotate(0.3) * Affine::translate(4, -6),
                                   Affine::scale(0.05)};
    const Affine m = kMaps[(head >> 1) & 7];
    // The scale of each map when it is a similarity (uniform scale, rotation, mirror, translation).
    static const double kSimilarityScale[] = {1, 1, 0, 0, 0, 1, 1, 0.05};
    const double similarity = kSimilarityScale[(head >> 1) & 7];
    static const double kTolerances[] = {kDefaultTolerance, 0.1, 0.5, 2};
    const double coarse = kTolerances[(head >> 4) & 3];

    Path path;
    bool curved = false;
    int ops = 0;
    while (in.more() && ops++ < 64) {
        switch (in.byte() % 7) {
            case 0: path.move_to(in.point()); break;
            case 1: path.line_to(in.point()); break;
            case 2: {
                const Point c = in.point();
                path.quad_to(c, in.point());
                curved = true;
                break;
            }
            case 3: {
                const Point c1 = in.point(), c2 = in.point();
                path.cubic_to(c1, c2, in.point());
                curved = true;
                break;
            }
            case 4: path.close(); break;
            case 5: {
                const double dx = static_cast<std::int8_t>(in.byte()) / 64.0,
                             dy = static_cast<std::int8_t>(in.byte()) / 64.0;
                // Stacked copies up to ~256 points: the exact cells cost grows with the square of the
                // edges inside one cell (thousands of stacked edges take seconds; see RELIABILITY.md).
                if (path.points().size() < 128) path.append(Path(path), Affine::translate(dx, dy));
                break;
            }
            case 6: {
                const Point c = in.point();
                const Point e = in.point();
                path.conic_to(c, e, 0.25 + in.byte() / 64.0);
                curved = true;
                break;
            }
        }
    }
    if (path.empty()) return 0;

    try {
        Rasterizer r;
        const Mask fast = render(r, path, m, opts);
        const Topology verdict = r.last_stats().topology;
        FillOptions exact = opts;
        exact.topology = Topology::Overlapping;
        exact.winding_sweep = false;
        const Mask cells = render(r, path, m, exact);
        // Exact everywhere: no cell fell back to lines or to accumulation for want of budget.
        const bool all_exact = r.last_stats().dense_cells == 0 && r.last_stats().accumulated_cells == 0;
        expect_close("default vs exact cells", fast, cells);
        expect_close("the exact cells in bands vs exact cells",
                     r.fill_mask(with_far_square(path, m, 1200), Affine{}, exact, IRect{0, 0, 1210, kSize}), cells);
        // The verdict: a path classify_topology proves simple, filled with that verdict (plain
        // accumulation) and with exact overlaps off, must match the exact cells.
        if (verdict == Topology::Simple || classify_topology(path) == Topology::Simple) {
            FillOptions given = opts;
            given.topology = Topology::Simple;
            expect_close("a Simple path through the fast path vs exact cells", render(r, path, m, given), cells);
            FillOptions plain = opts;
            plain.exact_overlaps = false;
            expect_close("plain accumulation of a Simple path vs exact cells", render(r, path, m, plain), cells);
            const Path wide = with_far_square(path, m);
            expect_close("plain accumulation in float cells vs exact cells",
                         r.fill_mask(wide, Affine{}, plain, IRect{0, 0, 610, kSize}), cells);
        }
        {
            FillOptions swept = opts;
            swept.topology = Topology::Overlapping;
            expect_close("the winding sweep vs exact cells", render(r, path, m, swept), cells);
            const Path wide = with_far_square(path, m);
            expect_close("the winding sweep in float cells vs exact cells",
                         r.fill_mask(wide, Affine{}, swept, IRect{0, 0, 610, kSize}), cells);
        }
        if (similarity > 0 && classify_topology(path, coarse / similarity) == Topology::Simple) {
            FillOptions plain = opts, cells_at = opts;
            plain.tolerance = cells_at.tolerance = coarse;
            plain.exact_overlaps = false;
            cells_at.topology = Topology::Overlapping;
            expect_close("plain accumulation of a path Simple under similarity maps vs exact cells",
                         render(r, path, m, plain), render(r, path, m, cells_at));
        }
        if (all_exact) {
            // Hidden pixels: every third, in diagonal stripes, or in a block, by bits 6-7.
            PixelSet hidden(IRect{0, 0, kSize, kSize});
            const int pattern = head >> 6;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x)
                    if ((pattern == 0 && (x + 2 * y) % 3 == 0) || (pattern == 1 && (x + y) % 7 < 3) ||
                        (pattern == 2 && x >= 8 && x < 24 && y >= 4 && y < 30) || pattern == 3)
                        hidden.insert(y, x, x + 1);
            FillOptions hide = exact, plain = opts;
            hide.hidden = &hidden;
            plain.exact_overlaps = false;
            const Mask partly = render(r, path, m, hide), accumulated = render(r, path, m, plain);
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    const int got = partly.at(x, y);
                    if (hidden.contains(x, y) && std::abs(got - accumulated.at(x, y)) > 1)
                        fail("a hidden pixel vs plain accumulation", x, y, got, accumulated.at(x, y));
                    if (!hidden.contains(x, y) && got != cells.at(x, y))
                        fail("a pixel not hidden vs exact cells", x, y, got, cells.at(x, y));
                }
        }
        if (!curved) {
            // The overlap check confined to find_overlap_region's boxes, found on the path as it
            // is and mapped by m (as render_map's MapCache finds them in one frame and maps them
            // into another): the exact cells' pixels.
            const OverlapRegion region = find_overlap_region(path);
            if (region.topology != Topology::Unknown) {
                std::vector<Rect> boxes;
                for (const Rect& b : region.boxes) boxes.push_back(m.map_bounds(b));
                FillOptions confined = exact;
                confined.topology = region.topology;
                confined.overlap_boxes = boxes;
                expect_close("the overlap check in find_overlap_region's boxes vs exact cells",
                             render(r, path, m, confined), cells);
            }
            const ref::CoverageGrid g = ref::path_reference(path, m, opts.rule, IRect{0, 0, kSize, kSize});
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    const double want = 255.0 * g.at(x, y);
                    if (std::abs(fast.at(x, y) - want) > 1.0)
                        fail("default vs reference_area", x, y, fast.at(x, y), static_cast<int>(std::lround(want)));
                }
        }
    } catch (const Error&) {
        // Limits (too many edges) are a documented outcome, not a finding.
    }
    return 0;
}
