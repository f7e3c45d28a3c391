// casteljau/paint.hpp: the paint stage's face: colours, the Pixmap (premultiplied RGBA8) that
// everything draws into, the Paint a fill uses, and the span compositors every drawer goes through.
//
// Colours are sRGB with straight (non-premultiplied) alpha in the API; a Pixmap stores
// premultiplied RGBA8, row-major, 4 bytes per pixel, top row first, rows `stride()` bytes apart.
// A Pixmap either owns its pixels or borrows caller-owned memory (Pixmap::borrow), which must
// outlive it. PNG files hold straight alpha (png.hpp converts).
// Thread-safety: values; distinct Pixmaps may be drawn on from distinct threads. A Paint is a value
// whose shader is immutable and may be shared between threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "casteljau/blend_mode.hpp"
#include "casteljau/geometry.hpp"

namespace casteljau {

// An sRGB colour with straight alpha, 8 bits per channel.
struct Color {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;

    static constexpr Color rgba(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255) {
        return {r, g, b, a};
    }
    static constexpr Color transparent() { return {0, 0, 0, 0}; }
    static constexpr Color black() { return {0, 0, 0, 255}; }
    static constexpr Color white() { return {255, 255, 255, 255}; }
    // The same colour with its alpha multiplied by `opacity` in [0, 1].
    Color with_opacity(double opacity) const;
    bool operator==(const Color&) const = default;
};

// Parses a CSS colour: #rgb, #rgba, #rrggbb, #rrggbbaa, rgb()/rgba() (numbers or percentages,
// comma or space syntax, optional "/ alpha"), hsl()/hsla(), the 148 CSS named colours
// (case-insensitive), `transparent` and `none` (both fully transparent).
// Throws Error(Parse) naming the text and what was expected.
Color parse_color(std::string_view text);

// A premultiplied RGBA8 pixel.
struct PremulPixel {
    std::uint8_t r = 0, g = 0, b = 0, a = 0;
    bool operator==(const PremulPixel&) const = default;
};
PremulPixel premultiply(Color c);
Color unpremultiply(PremulPixel p);

class Pixmap {
public:
    Pixmap() = default;
    // A transparent pixmap that owns its pixels (stride = 4 x width).
    // Memory kept: the pixels of released pixmaps of 2 MiB and more (up to 4 of them, 256 MiB in
    // all) stay mapped for the next pixmap of the same size, which then costs no page faults;
    // the kernel may reclaim them when it needs memory (MADV_FREE), and a large pixmap or buffer of
    // another size unmaps them.
    // Throws Error(Limit) when width or height exceeds Limits::canvas_dimension or the area
    // exceeds Limits::canvas_pixels (casteljau/limits.hpp), Error(InvalidArgument) when either is below 1.
    Pixmap(int width, int height);
    // A pixmap over caller-owned premultiplied RGBA8 memory (a window's back buffer, a texture):
    // `pixels` holds `height` rows of `stride` bytes, stride >= 4 x width. Nothing is copied or
    // cleared; the memory must outlive the Pixmap and every Canvas drawing into it.
    // Throws Error(InvalidArgument) for a null pointer, a stride below 4 x width or a size below
    // 1x1, Error(Limit) past the canvas limits.
    static Pixmap borrow(std::uint8_t* pixels, int width, int height, std::size_t stride);

    // Copies own their pixels (a copy of a borrowed pixmap is an owned, tightly packed copy).
    Pixmap(const Pixmap& o);
    Pixmap& operator=(const Pixmap& o);
    Pixmap(Pixmap&& o) noexcept;
    Pixmap& operator=(Pixmap&& o) noexcept;
    ~Pixmap() = default;

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t stride() const { return stride_; }  // bytes from one row to the next
    bool borrowed() const { return pixels_ != nullptr && !storage_; }
    // The first row. Rows are stride() bytes apart; only an owned pixmap is guaranteed contiguous.
    std::uint8_t* data() { return pixels_; }
    const std::uint8_t* data() const { return pixels_; }
    std::uint8_t* row(int y) { return pixels_ + stride_ * static_cast<std::size_t>(y); }
    const std::uint8_t* row(int y) const { return pixels_ + stride_ * static_cast<std::size_t>(y); }

    PremulPixel pixel(int x, int y) const;
    void set_pixel(int x, int y, PremulPixel p);
    void fill(Color c);  // replaces every pixel (no blending)
    // Replaces the pixels of rows [y0, y1) (clamped to the pixmap; no blending). Threads may fill
    // disjoint row ranges of one pixmap at once.
    void fill_rows(int y0, int y1, Color c);

private:
    // Internal (src/paint/pixmap_memory.hpp): a pixmap whose reused memory its maker clears.
    friend struct PixmapMemory;
    int width_ = 0, height_ = 0;
    std::size_t stride_ = 0;
    // Owned pixels (null when borrowed), zeroed memory from calloc or, for large pixmaps, mapped
    // on 2 MiB pages where the system allows: a large pixmap starts as zero pages that the kernel
    // maps on first touch (and whoever touches a row first, possibly a worker thread, pays for
    // its pages), or in the memory of a released pixmap of the same size, cleared when made.
    struct Free {
        Free() noexcept : bytes(0) {}
        explicit Free(std::size_t n) noexcept : bytes(n) {}
        void operator()(std::uint8_t* p) const noexcept;
        std::size_t bytes;  // as allocated
    };
    std::unique_ptr<std::uint8_t[], Free> storage_;
    std::uint8_t* pixels_ = nullptr;
};

class Shader;

// What a fill paints: a solid colour, or a Shader (gradient, image pattern; shader.hpp) evaluated
// per pixel when `shader` is set (then `color` is ignored). The shader's own transform maps its
// space to the user space of the fill; the Canvas's current transform at the time of the fill goes
// on top. `blend` combines the painted colour with the destination (blend_mode.hpp); a Canvas uses
// its own state's blend mode when the paint's is SourceOver.
struct Paint {
    Color color = Color::black();
    double opacity = 1.0;  // multiplies the colour's alpha
    bool linear_blend =
        false;  // blend coverage in linear light (gamma-correct) instead of sRGB; solid source-over only
    std::shared_ptr<const Shader> shader;
    BlendMode blend = BlendMode::SourceOver;

    static Paint solid(Color c) {
        Paint p;
        p.color = c;
        return p;
    }
    static Paint shaded(Shader s);
};

// Source-over of `paint` x coverage onto one row of premultiplied pixels (exposed for tests and
// for callers that rasterize themselves). `dst` points at pixel x of the row. With S the paint
// colour premultiplied (alpha = round(a x opacity), channels round(x a / 255)), coverage c and
// destination D, every channel becomes round((S c 255 + D (255^2 - Sa c)) / 255^2): the exact
// source-over value rounded once. With linear_blend the colour channels are blended in linear
// light and re-encoded to sRGB (within one level of the exact value). Neither a shader nor the
// paint's blend mode is handled here (see blend_span and Canvas).
void composite_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const Paint& paint);
// Source-over of per-pixel premultiplied RGBA8 colours `src` x coverage onto one row, each channel
// round((S c 255 + D (255^2 - Sa c)) / 255^2) as for composite_span.
void composite_span_premul(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src);
// Any blend mode: every pixel becomes D + c (B(S, D) - D), with B the mode's result for source S
// and destination D (blend_mode.hpp) and c the coverage / 255 (`coverage` null: full coverage).
// `src` holds one premultiplied pixel per destination pixel, or one for the whole span when
// `src_stride` is 0. SourceOver takes composite_span_premul's exact integer path.
void blend_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src, BlendMode mode,
                int src_stride = 4);

// Checks a requested canvas size against the limits; throws Error(Limit) / Error(InvalidData).
void check_canvas_size(double width, double height);

}  // namespace casteljau
