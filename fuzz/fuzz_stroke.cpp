// libFuzzer target: the stroker and dasher on arbitrary paths (fuzz/path_gen.hpp) and styles
// (widths from 0 to 1e30 and NaN, every cap and join, miter limits, dash arrays with zero, negative
// and huge entries, offsets), then the outline filled into a small mask. Invariants: bad input ends
// in casteljau::Error; the outline of a finite path with a finite positive width is finite; the
// overlap check's fill with stroke_outline()'s interior capsules (FillOptions::inside) equals its
// fill without, and the winding sweep's fill (default options) is within 1/255 of it.
// Outlines above kFillPoints points are not filled: a 200-verb path stroked 33 px wide with round
// joins at 0.05 px makes 674,549, whose fill is linear but 20 s under the sanitizers (0.4 s in
// Release), and 25,631 points piled into the 128 x 128 mask took 9 s there (0.36 s in Release),
// nearly all in exact cells; the rasterizer's cost on large paths is fuzz_raster's subject. For
// the same reason the exact cells' work budget (Limits::exact_work) is lowered to 1e5 piece visits
// plus the 2000 per segment: 6,799 points piled into 128 cells spent the default budget, 0.3 s per
// fill in Release and 12 s under the sanitizers. Past that the cells are integrated on lines,
// which fuzz_raster_diff checks; and the SharedBorders fills are skipped when the stroke's own
// fill spent more than kSharedBordersWork.
// SharedBorders (casteljau/map.hpp): the path's points made into closed rings, plus rings sharing
// runs of their segments (a run of each ring closed on itself, each ring reversed), go through it;
// stroking what it keeps with Butt caps must cover what stroking every ring covers, within 1/255
// (checked up to 10,000 outline points).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "casteljau/limits.hpp"
#include "casteljau/map.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/stroke.hpp"
#include "harness.hpp"
#include "stroke_case.hpp"

using namespace casteljau;

namespace {

constexpr std::size_t kFillPoints = 4000;
constexpr double kSharedBordersWork = 1e6;

void shared_borders_check(const Path& path, const StrokeStyle& style, const Affine& m, Rasterizer& raster) {
    std::vector<Path> rings;
    const auto verbs = path.verbs();
    const auto pts = path.points();
    std::size_t pi = 0;
    std::vector<Point> cur;
    auto flush = [&] {
        if (!cur.empty()) {
            Path r;
            r.add_polygon(cur, true);
            rings.push_back(r.reversed());
            const std::size_t a = cur.size() / 3, b = cur.size() - cur.size() / 4;
            if (b > a) {
                Path part;
                part.add_polygon(std::span<const Point>(cur).subspan(a, b - a), true);
                rings.push_back(std::move(part));
            }
            rings.push_back(std::move(r));
        }
        cur.clear();
    };
    for (Verb v : verbs) {
        if (v == Verb::Move) flush();
        for (int k = 0; k < verb_point_count(v); ++k) cur.push_back(pts[pi++]);
    }
    flush();
    StrokeStyle st = style;
    st.dashes.clear();
    StrokeStyle butt = st;
    butt.cap = LineCap::Butt;
    Path all, once;
    SharedBorders borders;
    for (const Path& r : rings) {
        all.append(stroke(r, st, m, 0.05));
        Path chains, whole;
        borders.add(r, chains, whole, stroke_merge_distance(m, 0.05));
        once.append(stroke(chains, butt, m, 0.05));
        once.append(stroke(whole, st, m, 0.05));
        if (all.points().size() + once.points().size() > kFillPoints)
            return;  // overlap-heavy fills cost seconds under the sanitizers
    }
    const IRect clip{0, 0, 128, 128};
    const Mask a = raster.fill_mask(all, m, FillOptions{}, clip);
    const Mask b = raster.fill_mask(once, m, FillOptions{}, clip);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x)
            fuzz::require(std::abs(int(a.at(x, y)) - int(b.at(x, y))) <= 1,
                          "SharedBorders: stroking what it keeps does not cover what every ring's stroke covers");
}

}  // namespace

// Outlines stop at 2^20 points instead of 2^24 (Limits::path_points): the stroker's work is linear
// in its outline, and a path stroked with round joins at a huge width reaches the full limit, which
// takes 7 s under the sanitizers. What happens at the limit (Error(Limit), no partial outline) is
// the same at any value; tests/stroke cover it at the default.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    Limits l = current_limits();
    l.path_points = std::size_t(1) << 20;
    l.exact_work = 100'000;
    set_limits(l);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Bytes in(data, size);
    const fuzz::StrokeCase c = fuzz::read_stroke_case(in);
    const StrokeStyle& st = c.style;
    const Affine& m = c.m;
    const Path& path = c.path;
    fuzz::run([&] {
        const StrokeOutline so = stroke_outline(path, st, m, 0.05);
        const Path& outline = so.outline;
        bool finite_in = std::isfinite(st.width) && st.width > 0;
        for (const Point& p : path.points()) finite_in = finite_in && std::isfinite(p.x) && std::isfinite(p.y);
        if (finite_in && std::abs(st.width) < 1e6) {
            bool finite_out = true;
            for (const Point& p : outline.points()) finite_out = finite_out && std::isfinite(p.x) && std::isfinite(p.y);
            fuzz::require(finite_out, "a finite path stroked with a finite width gave a non-finite outline");
        }
        if (outline.points().size() > kFillPoints) return;
        Rasterizer raster;
        const IRect clip{0, 0, 128, 128};
        // The capsules only spare the overlap check's exact cells, so with them the overlap check
        // must give the very pixels it gives without them.
        FillOptions cells;
        cells.winding_sweep = false;
        const Mask plain = raster.fill_mask(outline, m, cells, clip);
        const double work = raster.last_stats().exact_work;
        FillOptions hinted = cells;
        hinted.inside = so.inside;
        const Mask with_inside = raster.fill_mask(outline, m, hinted, clip);
        fuzz::require(plain.bounds == with_inside.bounds && plain.data == with_inside.data,
                      "a pixel inside the stroke's interior capsules is not full");
        // The winding sweep (default options) is exact too: within one level of the overlap check,
        // where float and double accumulation round differently.
        const Mask swept = raster.fill_mask(outline, m, FillOptions{}, clip);
        fuzz::require(swept.bounds == plain.bounds, "the winding sweep's mask has other bounds");
        for (std::size_t i = 0; i < swept.data.size(); ++i)
            fuzz::require(std::abs(int(swept.data[i]) - int(plain.data[i])) <= 1,
                          "the winding sweep is more than 1/255 from the overlap check");
        if (!finite_in || !(st.width < 1e6) || work > kSharedBordersWork) return;
        shared_borders_check(path, st, m, raster);
    });
    return 0;
}
