// casteljau/shader.hpp: paint servers evaluated per pixel by the compositor (paint stage).
//
// A Shader gives the colour of every pixel a fill covers: a raster image, or linear and radial (two-point conical,
// SVG 2: centre circle (cx, cy, r), focal circle (fx, fy, fr)) gradients with colour stops and the
// SVG spread methods pad, reflect and repeat. Colours between stops are interpolated in sRGB with
// straight alpha, then premultiplied (SVG's rule), in float, and rounded to 8 bits once per pixel,
// so a gradient has no steps beyond the 1/255 of its output.
// Coordinates: a shader is defined in its own gradient space; `transform` maps that space to the
// user space of the fill (a Canvas applies its current transform on top when it draws). The
// colour of a pixel is the colour at the pixel's centre (i + 0.5, j + 0.5).
// Ownership: an image shader shares ownership of its Pixmap (shared_ptr) and only reads it.
// Thread-safety: a Shader is an immutable value once built; share it between threads freely.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/paint.hpp"

namespace casteljau {

enum class SpreadMethod { Pad, Reflect, Repeat };

// How an image is sampled between its pixel centres: the nearest pixel, bilinear interpolation of
// the 2x2 neighbours, or bicubic (Catmull-Rom, 4x4 neighbours, clamped to valid premultiplied
// values). Edges are clamped (or wrap around for a repeating pattern).
enum class ImageSampling { Nearest, Bilinear, Bicubic };

struct GradientStop {
    double offset = 0;  // in [0, 1]
    Color color;        // sRGB, straight alpha
};

class Shader {
public:
    enum class Kind { Linear, Radial, Image };

    // The gradient from `p0` (offset 0) to `p1` (offset 1); colours are constant along lines
    // perpendicular to p0-p1. Offsets are clamped to [0, 1] and made non-decreasing (a stop
    // before its predecessor moves up to it, as SVG requires). Throws Error(InvalidArgument) for
    // an empty stop list.
    static Shader linear(Point p0, Point p1, std::vector<GradientStop> stops, SpreadMethod spread = SpreadMethod::Pad,
                         const Affine& transform = {});
    // The gradient whose offset-t circle interpolates the focal circle (focal, fr) at t = 0 and
    // the end circle (center, r) at t = 1; a point takes the largest t whose circle passes
    // through it with a radius >= 0, and points no such circle reaches stay unpainted.
    static Shader radial(Point center, double r, Point focal, double fr, std::vector<GradientStop> stops,
                         SpreadMethod spread = SpreadMethod::Pad, const Affine& transform = {});

    // A raster image: gradient space is the image's pixel space ([0, w] x [0, h]); outside it the
    // shader is transparent. `smooth`: bilinear sampling of the premultiplied pixels (edges
    // clamped); otherwise the nearest pixel. Throws Error(InvalidArgument) for a null or empty image.
    // `repeat`: the image tiles the whole plane instead (patterns).
    static Shader image(std::shared_ptr<const Pixmap> image, bool smooth = true, const Affine& transform = {},
                        bool repeat = false);
    static Shader image(std::shared_ptr<const Pixmap> image, ImageSampling sampling, const Affine& transform = {},
                        bool repeat = false);

    Kind kind() const { return kind_; }
    const Affine& transform() const { return transform_; }
    // This shader with `m` applied after its transform: gradient space -> m x transform().
    Shader transformed(const Affine& m) const {
        Shader s = *this;
        s.transform_ = m * transform_;
        return s;
    }
    const std::vector<GradientStop>& stops() const { return stops_; }
    SpreadMethod spread() const { return spread_; }

    // The gradient parameter at point `p` of gradient space before spreading; false where the
    // radial gradient is undefined (no circle through p).
    bool parameter(Point p, double& t) const;
    // The straight-alpha colour at parameter t (after the spread method), as floats in [0, 1].
    void color_at(double t, float rgba[4]) const;

    // Premultiplied RGBA8 colours of `length` pixels from (x, y) rightwards into `out`, with
    // `pixel_to_gradient` the inverse of (canvas transform x transform()) and the colour's alpha
    // multiplied by `opacity`.
    void shade_row(const Affine& pixel_to_gradient, int x, int y, int length, double opacity, std::uint8_t* out) const;

private:
    Shader() = default;
    Kind kind_ = Kind::Linear;
    Point p0_, p1_;           // linear: start, end; radial: p0_ focal centre, p1_ end centre
    double r0_ = 0, r1_ = 0;  // radial: focal and end radii
    std::vector<GradientStop> stops_;
    // The stops as shading reads them, built with stops_ (set_stops): per stop the offset, 1 /
    // (distance to the next offset; 0 for the last stop or a zero distance) and the colour, four
    // floats in [0, 255].
    std::vector<double> offsets_, inv_spans_;
    std::vector<float> rgba_;
    void set_stops(std::vector<GradientStop> stops);
    // The straight-alpha colour at spread parameter u, channels in [0, 255].
    void interpolate(double u, float rgba[4]) const;
    SpreadMethod spread_ = SpreadMethod::Pad;
    Affine transform_;
    std::shared_ptr<const Pixmap> image_;
    ImageSampling sampling_ = ImageSampling::Bilinear;
    bool repeat_ = false;
    void sample_bicubic(double u, double v, float c[4]) const;
    // Whether the gradient paints its last stop everywhere (a zero-length linear gradient, a zero end radius).
    bool constant() const;
    void shade_image_row(const Affine& pixel_to_image, int x, int y, int length, double opacity,
                         std::uint8_t* out) const;
};

}  // namespace casteljau
