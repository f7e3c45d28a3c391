// casteljau/filter.hpp: filter effects (the SVG / CSS filter model) on premultiplied pixmaps.
//
// A FilterGraph is a list of primitives (flood, offset, merge, blend, composite, Gaussian blur,
// drop shadow, colour matrix, component transfer, morphology, convolution, tile, image,
// turbulence, displacement map, diffuse and specular lighting), each reading earlier results (or
// the source graphic, or its alpha) and writing one result; the last result is the output. It
// knows nothing of SVG: a reader builds the graph, and apply_filter evaluates it.
//
// Coordinates: the graph's lengths, regions and light positions are in user units; apply_filter
// maps them to device pixels with the user -> device Affine it is given (lengths scale by the
// transform's x and y scale factors, regions by their device bounding box). The filter region is
// clipped to the source pixmap, which bounds memory and time: pixels outside the canvas do not take
// part. Intermediate images are premultiplied RGBA in floats, in linearRGB or sRGB as each
// primitive asks (colour-interpolation-filters); the source is sRGB.
// Thread-safety: a FilterGraph is an immutable value once built; apply_filter may run on distinct
// graphs and pixmaps from distinct threads (an Image primitive's `draw` callback must allow that).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "casteljau/blend_mode.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/paint.hpp"

namespace casteljau {

namespace filter {

// Where a primitive's input comes from.
struct Input {
    enum Kind { Previous, SourceGraphic, SourceAlpha, Result } kind = Previous;
    int index = 0;  // Result: the primitive whose result is read (an earlier one)
    static Input source_graphic() { return {SourceGraphic, 0}; }
    static Input source_alpha() { return {SourceAlpha, 0}; }
    static Input result(int i) { return {Result, i}; }
};

enum class EdgeMode { None, Duplicate, Wrap };
enum class CompositeOp { Over, In, Out, Atop, Xor, Arithmetic, Lighter };

// One channel's transfer function (feFuncR/G/B/A), on straight values in [0, 1].
struct TransferFunction {
    enum Type { Identity, Table, Discrete, Linear, Gamma } type = Identity;
    std::vector<double> table;
    double slope = 1, intercept = 0, amplitude = 1, exponent = 1, offset = 0;
    double apply(double c) const;
};

// A light source for the lighting primitives, positions in user units.
struct Light {
    enum Type { Distant, Point, Spot } type = Distant;
    double azimuth = 0, elevation = 0;  // Distant, degrees
    double x = 0, y = 0, z = 0;         // Point, Spot
    double tx = 0, ty = 0, tz = 0;      // Spot: points at
    double specular_exponent = 1;       // Spot
    std::optional<double> cone_angle;   // Spot: limitingConeAngle, degrees
};

struct Primitive {
    enum Op {
        Flood,
        Offset,
        Merge,
        Blend,
        Composite,
        GaussianBlur,
        DropShadow,
        ColorMatrix,
        ComponentTransfer,
        Morphology,
        ConvolveMatrix,
        Tile,
        Image,
        Turbulence,
        DisplacementMap,
        DiffuseLighting,
        SpecularLighting
    } op = Flood;
    std::vector<Input> inputs;  // in, in2 (Merge: every node)
    Rect subregion;             // user units; results are transparent outside it
    bool linear_rgb = true;     // color-interpolation-filters: linearRGB (true) or sRGB

    Color color = Color::black();  // Flood, DropShadow: flood colour (opacity folded in); lighting colour
    double dx = 0, dy = 0;         // Offset, DropShadow: user units
    double std_x = 0, std_y = 0;   // GaussianBlur, DropShadow: standard deviation, user units
    EdgeMode edge = EdgeMode::None;
    BlendMode blend = BlendMode::Normal;
    CompositeOp composite = CompositeOp::Over;
    double k1 = 0, k2 = 0, k3 = 0, k4 = 0;  // arithmetic
    std::array<double, 20> matrix{};        // ColorMatrix: 4x5, rows R G B A, on straight values
    std::array<TransferFunction, 4> funcs;  // ComponentTransfer: R G B A
    bool dilate = false;                    // Morphology: dilate (true) or erode
    double rx = 0, ry = 0;                  // Morphology radius, user units
    // ConvolveMatrix: kernel (order_x x order_y, row-major), divisor, bias, target, preserveAlpha.
    int order_x = 3, order_y = 3;
    std::vector<double> kernel;
    double divisor = 1, bias = 0;
    int target_x = 1, target_y = 1;
    bool preserve_alpha = false;
    // Image: draws its content into a transparent pixmap the size of the source with the given
    // user -> device transform (the primitive's own placement already applied by the builder).
    std::function<void(Pixmap&, const Affine&)> draw;
    // Turbulence (the Perlin noise of the SVG specification): base frequency, octaves, seed,
    // stitchTiles, fractalNoise (true) or turbulence. Octaves after the tenth are not computed
    // (together they move no 8-bit value by more than 1/2).
    double freq_x = 0, freq_y = 0;
    int octaves = 1;
    double seed = 0;
    bool stitch = false, fractal = false;
    // DisplacementMap: scale (user units), channel selectors 0..3 = R G B A.
    double scale = 0;
    int x_channel = 3, y_channel = 3;
    // Lighting.
    double surface_scale = 1, diffuse_constant = 1, specular_constant = 1, specular_exponent = 1;
    Light light;
};

struct FilterGraph {
    Rect region;  // the filter region, user units
    std::vector<Primitive> primitives;
};

// Evaluates `graph` on `source` (the element drawn alone on a transparent pixmap of the canvas's
// size, device pixels) and returns the filtered result as a pixmap of the same size, transparent
// outside the filter region. Throws Error(Limit) above Limits::filter_pixels (the region
// after clipping to the canvas) or Limits::filter_primitives (casteljau/limits.hpp), Error(InvalidData) for an input naming a later primitive.
Pixmap apply_filter(const FilterGraph& graph, const Affine& to_device, const Pixmap& source);

}  // namespace filter
}  // namespace casteljau
