// Internal: the colours of a run of gradient parameters, premultiplied RGBA8, with Highway's
// runtime dispatch (core/simd_dispatch.hpp), for Shader::shade_row.
//
// Each value is the scalar formula's, whatever the target (the same operations in the same order,
// no fused multiply-add): the parameter spread by the method, the two stops around it interpolated
// in float, the alpha scaled by the opacity and the channels premultiplied and rounded half up.
// Thread-safety: a pure function.
#pragma once

#include <cstddef>
#include <cstdint>

#include "casteljau/shader.hpp"

namespace casteljau::paint_simd {

// The stops as shading reads them: per stop its offset (non-decreasing), 1 / (distance to the next
// offset; 0 for the last stop or a zero distance) and its colour, floats in [0, 255].
struct GradientTable {
    const double* offset;
    const double* inv_span;
    const float* rgba;  // 4 per stop
    std::size_t stops;  // >= 1
};

// Room the parameters need after the n values given (whole vectors are read).
inline constexpr int kGradientPadding = 64;

// Writes the premultiplied colours of parameters t[0, n) to out (4 bytes each): a NaN parameter
// gives a transparent pixel; `constant`: every valid pixel takes the last stop. t holds
// n + kGradientPadding values (those past n are read, not used).
void gradient_colors(const double* t, int n, const GradientTable& table, SpreadMethod spread, bool constant,
                     float opacity, std::uint8_t* out);

// A two-point conical (radial) gradient: focal circle (focal, r0), end circle (centre, r1), r1 > 0.
struct RadialGradient {
    Point focal, centre;
    double r0, r1;
};

// The gradient parameter t of the points p = origin + (x0 + i) step, i in [0, n) (x0 a whole
// number): the largest root of |p - c(t)| = r(t), c(t) = focal + t (centre - focal),
// r(t) = r0 + t (r1 - r0), whose radius is not negative; NaN where there is none. Shader::parameter
// and Shader::shade_row both use it. t holds n + kGradientPadding values.
void radial_parameters(const RadialGradient& g, Point origin, Point step, double x0, int n, double* t);

}  // namespace casteljau::paint_simd
