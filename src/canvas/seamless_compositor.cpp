// Canvas stage: the SeamlessCompositor (see include/casteljau/seamless.hpp), a SpanSink that hands
// each pixel's remaining area to the fill being added.
#include "casteljau/seamless.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

#include "casteljau/error.hpp"
#include "core/pixel_memory.hpp"
#include "paint/pixel_math.hpp"

namespace casteljau {

SeamlessCompositor::SeamlessCompositor(int width, int height) : SeamlessCompositor(IRect{0, 0, width, height}) {}

SeamlessCompositor::SeamlessCompositor(const IRect& region) { reset(region); }

SeamlessCompositor::SeamlessCompositor(Pixmap& target, const IRect& region) { reset_into(target, region); }

void SeamlessCompositor::reset(const IRect& region) {
    check_canvas_size(region.x1 - region.x0, region.y1 - region.y0);
    if (region.empty()) throw Error(ErrorKind::InvalidArgument, "compositor size must be positive");
    const bool keep_layer = !into_ && same_size(region);
    start(region, keep_layer);  // an own layer of the same size is cleared where fills touched it
    if (!keep_layer) layer_.assign(coverage_cells(region) * 4, 0);
    into_ = nullptr;
}

void SeamlessCompositor::reset_into(Pixmap& target, const IRect& region) {
    if (region.empty()) throw Error(ErrorKind::InvalidArgument, "compositor size must be positive");
    if (region.x0 < 0 || region.y0 < 0 || region.x1 > target.width() || region.y1 > target.height())
        throw Error(ErrorKind::InvalidArgument,
                    "SeamlessCompositor::reset_into: the target does not contain the region");
    start(region, false);  // pixels already written into a target stay there
    layer_.clear();
    layer_.shrink_to_fit();
    into_ = &target;
}

bool SeamlessCompositor::same_size(const IRect& region) const {
    return !lo_.empty() && region.x1 - region.x0 == width() && region.y1 - region.y0 == height();
}

std::size_t SeamlessCompositor::coverage_cells(const IRect& region) {
    return static_cast<std::size_t>(region.x1 - region.x0) * static_cast<std::size_t>(region.y1 - region.y0);
}

void SeamlessCompositor::start(const IRect& region, bool clear_layer) {
    if (same_size(region)) {
        forget(clear_layer);  // only what the last fills touched
    } else {
        const std::size_t n = coverage_cells(region);
        cov_.reset();
        cov_ = std::unique_ptr<std::uint8_t[], FreeCoverage>(static_cast<std::uint8_t*>(platform::allocate(n, true)),
                                                             FreeCoverage{n});
        if (!cov_) throw std::bad_alloc();
        lo_.assign(static_cast<std::size_t>(region.y1 - region.y0), region.x1 - region.x0);
        hi_.assign(static_cast<std::size_t>(region.y1 - region.y0), 0);
    }
    region_ = region;
}

std::uint8_t* SeamlessCompositor::layer_origin() const {
    if (into_) return into_->row(region_.y0) + static_cast<std::size_t>(region_.x0) * 4;
    return const_cast<std::uint8_t*>(layer_.data());
}

std::size_t SeamlessCompositor::layer_stride() const {
    return into_ ? into_->stride() : static_cast<std::size_t>(width()) * 4;
}

void SeamlessCompositor::clear() { forget(true); }

void SeamlessCompositor::FreeCoverage::operator()(std::uint8_t* p) const noexcept { platform::release(p, bytes); }

void SeamlessCompositor::forget(bool layer_too) {
    const std::size_t w = static_cast<std::size_t>(width());
    std::uint8_t* const layer = layer_origin();
    const std::size_t stride = layer_stride();
    for (std::size_t r = 0; r < lo_.size(); ++r) {
        if (lo_[r] >= hi_[r]) continue;
        const std::size_t lo = static_cast<std::size_t>(lo_[r]), len = static_cast<std::size_t>(hi_[r] - lo_[r]);
        if (layer_too) std::memset(layer + r * stride + lo * 4, 0, len * 4);
        std::memset(cov_.get() + r * w + lo, 0, len);
        lo_[r] = width();
        hi_[r] = 0;
    }
}

namespace {

using pixel::mul_div255;

// A colour's pixels at every coverage, for pixels no fill has taken yet: scaled[a] is
// mul_div255(a, c) per channel. Such a pixel's layer value is zero (the layer is cleared with the
// coverage, and reset_into requires a transparent target), so it becomes exactly scaled[a].
struct ScaledColour {
    PremulPixel c{};
    bool made = false;
    std::uint32_t scaled[256];
    std::uint8_t colour8[32];  // the colour eight times
};

// The table of colour c. A map fills hundreds of features in one colour, and making the table
// costs more than a small fill's pixels, so each thread keeps the last one it made.
const ScaledColour& scaled_colour(PremulPixel c) {
    thread_local ScaledColour t;
    if (t.made && t.c == c) return t;
    t.c = c;
    t.made = true;
    for (int k = 0; k < 8; ++k) std::memcpy(t.colour8 + 4 * k, &c, 4);
    for (unsigned a = 0; a < 256; ++a) {
        const std::uint8_t px[4] = {mul_div255(a, c.r), mul_div255(a, c.g), mul_div255(a, c.b), mul_div255(a, c.a)};
        std::memcpy(&t.scaled[a], px, 4);
    }
    return t;
}

struct SeamlessSink final : SpanSink {
    std::uint8_t* layer;  // the layer's pixel at the region's origin
    std::size_t layer_stride;
    std::uint8_t* cov;
    int* lo;
    int* hi;
    int width, x0, y0;  // the region's width and origin
    // scaled_colour() of the fill's colour, copied: the sink's own arrays are read without
    // reloading a pointer after every store into the layer.
    ScaledColour table;
    void set_colour(PremulPixel colour) { table = scaled_colour(colour); }
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        if (length <= 0) return;
        const std::size_t at =
            static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x - x0);
        int& l = lo[y - y0];
        int& h = hi[y - y0];
        l = std::min(l, x - x0);
        h = std::max(h, x - x0 + length);
        std::uint8_t* L =
            layer + static_cast<std::size_t>(y - y0) * layer_stride + static_cast<std::size_t>(x - x0) * 4;
        std::uint8_t* C = cov + at;
        constexpr std::uint64_t kNone = 0, kFull = ~std::uint64_t(0);
        int i = 0;
        // Eight pixels at a time: skipped where the fill leaves them alone (coverage 0); where no
        // fill has taken any of them yet, each takes its whole coverage (scaled colours).
        for (; i + 8 <= length; i += 8) {
            std::uint64_t a8, t8;
            std::memcpy(&a8, coverage + i, 8);
            if (a8 == kNone) continue;
            std::memcpy(&t8, C + i, 8);
            if (t8 == kNone) {
                std::memcpy(C + i, &a8, 8);
                std::uint8_t* const out = L + 4 * static_cast<std::size_t>(i);
                if (a8 == kFull)
                    std::memcpy(out, table.colour8, 32);
                else
                    for (int k = 0; k < 8; ++k) std::memcpy(out + 4 * k, &table.scaled[coverage[i + k]], 4);
                continue;
            }
            for (int k = i; k < i + 8; ++k) pixel(coverage[k], C[k], L + 4 * static_cast<std::size_t>(k));
        }
        for (; i < length; ++i) pixel(coverage[i], C[i], L + 4 * static_cast<std::size_t>(i));
    }
    // One pixel: coverage a of this fill, t the coverage already taken, l the layer's pixel.
    void pixel(unsigned a, std::uint8_t& t, std::uint8_t* l) const {
        if (a == 0) return;
        const unsigned total = t;
        if (total == 0) {  // first to cover: the layer is zero here
            t = static_cast<std::uint8_t>(a);
            std::memcpy(l, &table.scaled[a], 4);
            return;
        }
        const unsigned rem = 255u - total;
        if (rem == 0) return;
        unsigned take = a < rem ? a : rem;
        // Two fills meeting at an edge whose rounded coverages fall one short of full.
        if (take + 1 == rem) take = rem;
        t = static_cast<std::uint8_t>(total + take);
        const unsigned na = std::min(255u, unsigned(l[3]) + mul_div255(take, table.c.a));
        l[0] = static_cast<std::uint8_t>(std::min(na, unsigned(l[0]) + mul_div255(take, table.c.r)));
        l[1] = static_cast<std::uint8_t>(std::min(na, unsigned(l[1]) + mul_div255(take, table.c.g)));
        l[2] = static_cast<std::uint8_t>(std::min(na, unsigned(l[2]) + mul_div255(take, table.c.b)));
        l[3] = static_cast<std::uint8_t>(na);
    }
};

// Sets `length` pixels from `row` to p.
void fill_span(std::uint8_t* row, int length, PremulPixel p) {
    const std::size_t n = static_cast<std::size_t>(length);
    if (p.r == p.g && p.g == p.b && p.b == p.a) {  // transparent, opaque black or white: one byte value
        std::memset(row, p.r, 4 * n);
        return;
    }
    const std::uint8_t px[4] = {p.r, p.g, p.b, p.a};
    for (std::size_t i = 0; i < n; ++i) std::memcpy(row + 4 * i, px, 4);
}

}  // namespace

void SeamlessCompositor::add(Rasterizer& raster, const Path& path, const FillOptions& opts, Color color,
                             double opacity) {
    add(raster, path, opts, color, opacity, region_);
}

void SeamlessCompositor::add(Rasterizer& raster, const Path& path, const FillOptions& opts, Color color, double opacity,
                             const IRect& clip) {
    const IRect c{std::max(clip.x0, region_.x0), std::max(clip.y0, region_.y0), std::min(clip.x1, region_.x1),
                  std::min(clip.y1, region_.y1)};
    if (c.empty()) return;
    SeamlessSink sink;
    sink.layer = layer_origin();
    sink.layer_stride = layer_stride();
    sink.cov = cov_.get();
    sink.lo = lo_.data();
    sink.hi = hi_.data();
    sink.width = width();
    sink.x0 = region_.x0;
    sink.y0 = region_.y0;
    sink.set_colour(premultiply(color.with_opacity(std::clamp(opacity, 0.0, 1.0))));
    raster.fill(path, Affine{}, opts, c, sink);
}

void SeamlessCompositor::composite_onto(Pixmap& dst) const {
    if (into_ == &dst) return;  // the layer is dst's own pixels
    composite_rows(dst, nullptr);
}

void SeamlessCompositor::composite_onto(Pixmap& dst, Color background) const {
    if (into_)
        throw Error(ErrorKind::InvalidArgument,
                    "SeamlessCompositor::composite_onto: a background needs a layer of its own (not reset_into)");
    const PremulPixel b = premultiply(background);
    composite_rows(dst, &b);
}

void SeamlessCompositor::composite_rows(Pixmap& dst, const PremulPixel* background) const {
    if (region_.x0 < 0 || region_.y0 < 0 || region_.x1 > dst.width() || region_.y1 > dst.height())
        throw Error(ErrorKind::InvalidArgument,
                    "SeamlessCompositor::composite_onto: the target does not contain the region");
    for (int y = region_.y0; y < region_.y1; ++y) {
        const std::size_t r = static_cast<std::size_t>(y - region_.y0);
        std::uint8_t* const row = dst.row(y) + static_cast<std::size_t>(region_.x0) * 4;
        if (background) fill_span(row, width(), *background);
        if (lo_[r] >= hi_[r]) continue;  // no fill touched the row: the layer is transparent there
        const std::size_t lo = static_cast<std::size_t>(lo_[r]);
        composite_span_premul(row + lo * 4, hi_[r] - lo_[r], nullptr, layer_origin() + r * layer_stride() + lo * 4);
    }
}

}  // namespace casteljau
