// Paint stage: gradient shaders (include/casteljau/shader.hpp). Each pixel maps its centre back
// into gradient space, finds the gradient parameter (a projection for linear gradients, the
// largest root of the two-point conical equation for radial ones), spreads it, interpolates the
// two neighbouring stops in float and premultiplies.
#include "casteljau/shader.hpp"

#include <algorithm>
#include <cmath>

#include "casteljau/error.hpp"
#include "paint/gradient_span.hpp"

namespace casteljau {

namespace {

std::vector<GradientStop> normalise(std::vector<GradientStop> stops) {
    if (stops.empty()) throw Error(ErrorKind::InvalidArgument, "a gradient needs at least one stop");
    double prev = 0;
    for (GradientStop& s : stops) {
        const double o = std::isfinite(s.offset) ? std::clamp(s.offset, 0.0, 1.0) : 0.0;
        s.offset = std::max(o, prev);
        prev = s.offset;
    }
    return stops;
}

double spread_t(double t, SpreadMethod m) {
    switch (m) {
        case SpreadMethod::Pad: return std::clamp(t, 0.0, 1.0);
        case SpreadMethod::Repeat: return t - std::floor(t);
        case SpreadMethod::Reflect: {
            double u = std::fmod(std::fabs(t), 2.0);
            return u > 1 ? 2 - u : u;
        }
    }
    return t;
}

}  // namespace

void Shader::set_stops(std::vector<GradientStop> stops) {
    stops_ = normalise(std::move(stops));
    const std::size_t n = stops_.size();
    offsets_.resize(n);
    inv_spans_.resize(n);
    rgba_.resize(4 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const Color& c = stops_[i].color;
        const double span = i + 1 < n ? stops_[i + 1].offset - stops_[i].offset : 0;
        offsets_[i] = stops_[i].offset;
        inv_spans_[i] = span > 0 ? 1 / span : 0;
        const float channels[4] = {float(c.r), float(c.g), float(c.b), float(c.a)};
        std::copy(channels, channels + 4, rgba_.begin() + static_cast<std::ptrdiff_t>(4 * i));
    }
}

void Shader::interpolate(double u, float rgba[4]) const {
    const std::size_t n = offsets_.size();
    auto put = [&](std::size_t stop) {
        for (int k = 0; k < 4; ++k) rgba[k] = rgba_[4 * stop + static_cast<std::size_t>(k)];
    };
    if (u <= offsets_[0]) return put(0);
    if (u >= offsets_[n - 1]) return put(n - 1);
    std::size_t i = 1;
    while (offsets_[i] <= u) ++i;  // offsets_[i - 1] <= u < offsets_[i]
    const float* c0 = rgba_.data() + 4 * (i - 1);
    const float* c1 = rgba_.data() + 4 * i;
    const float w = inv_spans_[i - 1] > 0 ? static_cast<float>((u - offsets_[i - 1]) * inv_spans_[i - 1]) : 1.0f;
    for (int k = 0; k < 4; ++k) rgba[k] = c0[k] + (c1[k] - c0[k]) * w;
}

Shader Shader::linear(Point p0, Point p1, std::vector<GradientStop> stops, SpreadMethod spread,
                      const Affine& transform) {
    Shader s;
    s.kind_ = Kind::Linear;
    s.p0_ = p0;
    s.p1_ = p1;
    s.set_stops(std::move(stops));
    s.spread_ = spread;
    s.transform_ = transform;
    return s;
}

Shader Shader::radial(Point center, double r, Point focal, double fr, std::vector<GradientStop> stops,
                      SpreadMethod spread, const Affine& transform) {
    Shader s;
    s.kind_ = Kind::Radial;
    s.p0_ = focal;
    s.p1_ = center;
    s.r0_ = std::isfinite(fr) ? std::max(fr, 0.0) : 0.0;
    s.r1_ = std::isfinite(r) ? std::max(r, 0.0) : 0.0;
    s.set_stops(std::move(stops));
    s.spread_ = spread;
    s.transform_ = transform;
    return s;
}

bool Shader::parameter(Point p, double& t) const {
    if (kind_ == Kind::Image) return false;
    if (kind_ == Kind::Linear) {
        const double dx = p1_.x - p0_.x, dy = p1_.y - p0_.y;
        const double len2 = dx * dx + dy * dy;
        if (!(len2 > 0)) {
            t = 1;  // a zero-length gradient paints its last stop everywhere
            return true;
        }
        t = ((p.x - p0_.x) * dx + (p.y - p0_.y) * dy) / len2;
        return true;
    }
    if (r1_ == 0) {
        t = 1;  // a zero end radius paints the last stop everywhere (SVG)
        return true;
    }
    // The conical equation of paint_simd::radial_parameters, for this one point.
    double out[1 + paint_simd::kGradientPadding];
    paint_simd::radial_parameters({p0_, p1_, r0_, r1_}, p, {0, 0}, 0, 1, out);
    t = out[0];
    return !std::isnan(t);
}

bool Shader::constant() const { return (kind_ == Kind::Linear && p0_ == p1_) || (kind_ == Kind::Radial && r1_ == 0); }

void Shader::color_at(double t, float rgba[4]) const {
    interpolate(constant() ? 1.0 : spread_t(t, spread_), rgba);
    for (int k = 0; k < 4; ++k) rgba[k] *= 1.0f / 255.0f;
}

// Every pixel's parameter is computed from its own position (the row's start plus x times the
// step along the row), so a pixel's colour does not depend on which span it was shaded in.
void Shader::shade_row(const Affine& inv, int x, int y, int length, double opacity, std::uint8_t* out) const {
    if (kind_ == Kind::Image) return shade_image_row(inv, x, y, length, opacity, out);
    const float op = static_cast<float>(std::clamp(opacity, 0.0, 1.0));
    const paint_simd::GradientTable table{offsets_.data(), inv_spans_.data(), rgba_.data(), offsets_.size()};
    const Point row = inv.apply({0.5, y + 0.5});  // the centre of the row's pixel 0
    const double dx = p1_.x - p0_.x, dy = p1_.y - p0_.y, len2 = dx * dx + dy * dy;
    const bool linear = kind_ == Kind::Linear && len2 > 0;
    // The parameter is affine along a row of a linear gradient: t(X) = t(0) + X dt, no division
    // per pixel. Radial gradients solve their equation per pixel; NaN marks no circle.
    const double t0 = linear ? ((row.x - p0_.x) * dx + (row.y - p0_.y) * dy) / len2 : 0;
    const double dt = linear ? (inv.a * dx + inv.b * dy) / len2 : 0;
    constexpr int kChunk = 256;
    double ts[kChunk + paint_simd::kGradientPadding] = {};
    const bool radial = kind_ == Kind::Radial && r1_ != 0;
    for (int from = 0; from < length; from += kChunk) {
        const int n = std::min(kChunk, length - from);
        if (radial) {
            paint_simd::radial_parameters({p0_, p1_, r0_, r1_}, row, {inv.a, inv.b}, x + from, n, ts);
        } else if (linear) {
            for (int i = 0; i < n; ++i) ts[i] = t0 + (x + from + i) * dt;
        } else {
            std::fill(ts, ts + n, 1.0);  // a zero-length linear gradient or a zero end radius
        }
        paint_simd::gradient_colors(ts, n, table, spread_, constant(), op, out + 4 * static_cast<std::size_t>(from));
    }
}

}  // namespace casteljau
