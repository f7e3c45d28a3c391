// libFuzzer target: the stroker and dasher on arbitrary paths (fuzz/path_gen.hpp) and styles
// (widths from 0 to 1e30 and NaN, every cap and join, miter limits, dash arrays with zero, negative
// and huge entries, offsets), then the outline filled into a small mask. Invariants: bad input ends
// in casteljau::Error; the outline of a finite path with a finite positive width is finite.
// Outlines above 100,000 points are not filled: a 200-verb path stroked 33 px wide with round
// joins at 0.05 px makes 674,549, whose fill is linear but 20 s under the sanitizers (0.4 s in
// Release); the rasterizer's cost on large paths is fuzz_raster's subject.
#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/raster.hpp"
#include "casteljau/stroke.hpp"
#include "harness.hpp"
#include "stroke_case.hpp"

using namespace casteljau;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Bytes in(data, size);
    const fuzz::StrokeCase c = fuzz::read_stroke_case(in);
    const StrokeStyle& st = c.style;
    const Affine& m = c.m;
    const Path& path = c.path;
    fuzz::run([&] {
        const Path outline = stroke(path, st, m, 0.05);
        bool finite_in = std::isfinite(st.width) && st.width > 0;
        for (const Point& p : path.points()) finite_in = finite_in && std::isfinite(p.x) && std::isfinite(p.y);
        if (finite_in && std::abs(st.width) < 1e6) {
            bool finite_out = true;
            for (const Point& p : outline.points()) finite_out = finite_out && std::isfinite(p.x) && std::isfinite(p.y);
            fuzz::require(finite_out, "a finite path stroked with a finite width gave a non-finite outline");
        }
        if (outline.points().size() > 100000) return;
        Rasterizer raster;
        (void)raster.fill_mask(outline, m, FillOptions{}, IRect{0, 0, 128, 128});
    });
    return 0;
}
