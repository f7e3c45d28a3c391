// casteljau/paint.hpp: colours and the Pixmap (premultiplied RGBA8) that everything draws into.
//
// Colours are sRGB with straight (non-premultiplied) alpha in the API; a Pixmap stores
// premultiplied RGBA8, row-major, 4 bytes per pixel, top row first. PNG files hold straight alpha
// (png.hpp converts). Thread-safety: values; distinct Pixmaps may be drawn on from distinct threads.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

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
    // Throws Error(Limit) when width or height exceeds limits::kMaxCanvasDimension or the area
    // exceeds limits::kMaxCanvasPixels, Error(InvalidArgument) when either is below 1.
    Pixmap(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t stride() const { return static_cast<std::size_t>(width_) * 4; }  // bytes per row
    std::uint8_t* data() { return data_.data(); }
    const std::uint8_t* data() const { return data_.data(); }
    std::uint8_t* row(int y) { return data_.data() + stride() * static_cast<std::size_t>(y); }
    const std::uint8_t* row(int y) const { return data_.data() + stride() * static_cast<std::size_t>(y); }

    PremulPixel pixel(int x, int y) const;
    void set_pixel(int x, int y, PremulPixel p);
    void fill(Color c);  // replaces every pixel (no blending)

private:
    int width_ = 0, height_ = 0;
    std::vector<std::uint8_t> data_;
};

// Checks a requested canvas size against the limits; throws Error(Limit) / Error(InvalidData).
void check_canvas_size(double width, double height);

}  // namespace casteljau
