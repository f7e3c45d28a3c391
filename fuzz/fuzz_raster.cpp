// libFuzzer target: the rasterizer on arbitrary paths (fuzz/path_gen.hpp: random verbs, NaN,
// infinities, 1e30, denormals, zero-length and very many segments), any transform, fill rule,
// exactness and tolerance, clipped to a random rectangle. Invariants: bad geometry ends in
// casteljau::Error; a mask always has exactly the clip's size; coverage never leaves the clip;
// the span sink receives rows in increasing y inside the clip.
#include "casteljau/raster.hpp"
#include "harness.hpp"
#include "path_gen.hpp"

using namespace casteljau;

namespace {

struct CheckingSink final : SpanSink {
    IRect clip;
    int last_y = -2147483647;
    void row(int y, int x, int length, const std::uint8_t*) override {
        fuzz::require(y >= clip.y0 && y < clip.y1, "row outside the clip");
        fuzz::require(x >= clip.x0 && length >= 0 && x + length <= clip.x1, "span outside the clip");
        fuzz::require(y >= last_y, "rows out of order");
        last_y = y;
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Bytes in(data, size);
    FillOptions opts;
    opts.rule = in.flag() ? FillRule::EvenOdd : FillRule::NonZero;
    opts.exact_overlaps = in.flag();
    static const double kTolerance[] = {0.015, 0.25, 1e-4, 4.0};
    opts.tolerance = kTolerance[in.byte() % 4];
    Affine m{};
    if (in.flag()) m = Affine{in.number(8), in.number(2), in.number(2), in.number(8), in.number(300), in.number(300)};
    const int x0 = in.range(-64, 256), y0 = in.range(-64, 256);
    const IRect clip{x0, y0, x0 + in.range(0, 256), y0 + in.range(0, 256)};
    const Path path = fuzz::random_path(in, 300);
    Rasterizer raster;
    fuzz::run([&] {
        const Mask mask = raster.fill_mask(path, m, opts, clip);
        fuzz::require(mask.bounds == clip || (clip.empty() && mask.data.empty()), "mask bounds differ from the clip");
        fuzz::require(mask.data.size() == static_cast<std::size_t>(std::max(clip.width(), 0)) *
                                              static_cast<std::size_t>(std::max(clip.height(), 0)) ||
                          clip.empty(),
                      "mask size is not the clip's size");
    });
    fuzz::run([&] {
        CheckingSink sink;
        sink.clip = clip;
        raster.fill(path, m, opts, clip, sink);
    });
    return 0;
}
