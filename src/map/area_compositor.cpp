// Map stage: the AreaCompositor (see include/casteljau/seamless.hpp), a SpanSink that hands each
// pixel's remaining area to the fill being added.
#include <algorithm>
#include <cmath>

#include "casteljau/error.hpp"
#include "casteljau/seamless.hpp"

namespace casteljau {

AreaCompositor::AreaCompositor(int width, int height) : width_(width), height_(height) {
    check_canvas_size(width, height);
    if (width < 1 || height < 1) throw Error(ErrorKind::InvalidArgument, "compositor size must be positive");
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    layer_.assign(n * 4, 0);
    cov_.assign(n, 0);
}

void AreaCompositor::clear() {
    std::fill(layer_.begin(), layer_.end(), 0);
    std::fill(cov_.begin(), cov_.end(), 0);
}

namespace {

inline std::uint8_t mul255(unsigned a, unsigned b) { return static_cast<std::uint8_t>((a * b + 127) / 255); }

struct AreaSink final : SpanSink {
    std::uint8_t* layer;
    std::uint8_t* cov;
    int width;
    PremulPixel c;
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        std::uint8_t* L = layer + (static_cast<std::size_t>(y) * width + x) * 4;
        std::uint8_t* C = cov + static_cast<std::size_t>(y) * width + x;
        for (int i = 0; i < length; ++i, L += 4) {
            const unsigned a = coverage[i];
            if (a == 0) continue;
            const unsigned total = C[i];
            const unsigned rem = 255u - total;
            if (rem == 0) continue;
            unsigned take = a < rem ? a : rem;
            // Two fills meeting at an edge whose rounded coverages fall one short of full.
            if (total > 0 && take + 1 == rem) take = rem;
            C[i] = static_cast<std::uint8_t>(total + take);
            const unsigned na = std::min(255u, unsigned(L[3]) + mul255(take, c.a));
            L[0] = static_cast<std::uint8_t>(std::min(na, unsigned(L[0]) + mul255(take, c.r)));
            L[1] = static_cast<std::uint8_t>(std::min(na, unsigned(L[1]) + mul255(take, c.g)));
            L[2] = static_cast<std::uint8_t>(std::min(na, unsigned(L[2]) + mul255(take, c.b)));
            L[3] = static_cast<std::uint8_t>(na);
        }
    }
};

}  // namespace

void AreaCompositor::add(Rasterizer& raster, const Path& path, const FillOptions& opts, Color color, double opacity) {
    add(raster, path, opts, color, opacity, IRect{0, 0, width_, height_});
}

void AreaCompositor::add(Rasterizer& raster, const Path& path, const FillOptions& opts, Color color, double opacity,
                         const IRect& clip) {
    const IRect c{std::max(clip.x0, 0), std::max(clip.y0, 0), std::min(clip.x1, width_), std::min(clip.y1, height_)};
    if (c.empty()) return;
    AreaSink sink;
    sink.layer = layer_.data();
    sink.cov = cov_.data();
    sink.width = width_;
    sink.c = premultiply(color.with_opacity(std::clamp(opacity, 0.0, 1.0)));
    raster.fill(path, Affine{}, opts, c, sink);
}

void AreaCompositor::composite_onto(Pixmap& dst) const {
    if (dst.width() != width_ || dst.height() != height_)
        throw Error(ErrorKind::InvalidArgument, "AreaCompositor::composite_onto: size mismatch");
    const std::size_t n = static_cast<std::size_t>(width_) * height_;
    std::uint8_t* d = dst.data();
    const std::uint8_t* s = layer_.data();
    for (std::size_t i = 0; i < n; ++i, d += 4, s += 4) {
        const unsigned sa = s[3];
        if (sa == 0) continue;
        if (sa == 255) {
            d[0] = s[0]; d[1] = s[1]; d[2] = s[2]; d[3] = 255;
            continue;
        }
        const unsigned inv = 255 - sa;
        for (int k = 0; k < 4; ++k) d[k] = static_cast<std::uint8_t>(s[k] + mul255(d[k], inv));
    }
}

}  // namespace casteljau
