// Paint stage: gradient shaders (include/casteljau/shader.hpp). Each pixel maps its centre back
// into gradient space, finds the gradient parameter (a projection for linear gradients, the
// largest root of the two-point conical equation for radial ones), spreads it, interpolates the
// two neighbouring stops in float and premultiplies.
#include "casteljau/shader.hpp"

#include <algorithm>
#include <cmath>

#include "casteljau/error.hpp"

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

// The straight-alpha colour of the normalised stops at spread parameter u, as floats in [0, 1].
[[gnu::always_inline]] inline void eval_stops(const std::vector<GradientStop>& stops, double u, float rgba[4]) {
    auto put = [&](const Color& c) {
        rgba[0] = c.r / 255.0f;
        rgba[1] = c.g / 255.0f;
        rgba[2] = c.b / 255.0f;
        rgba[3] = c.a / 255.0f;
    };
    if (u <= stops.front().offset) return put(stops.front().color);
    if (u >= stops.back().offset) return put(stops.back().color);
    std::size_t i = 1;
    while (i < stops.size() && stops[i].offset <= u) ++i;  // stops[i - 1].offset <= u < stops[i].offset
    const GradientStop& s0 = stops[i - 1];
    const GradientStop& s1 = stops[i];
    const double span = s1.offset - s0.offset;
    const float w = span > 0 ? static_cast<float>((u - s0.offset) / span) : 1.0f;
    rgba[0] = (s0.color.r + (s1.color.r - s0.color.r) * w) / 255.0f;
    rgba[1] = (s0.color.g + (s1.color.g - s0.color.g) * w) / 255.0f;
    rgba[2] = (s0.color.b + (s1.color.b - s0.color.b) * w) / 255.0f;
    rgba[3] = (s0.color.a + (s1.color.a - s0.color.a) * w) / 255.0f;
}

}  // namespace

Shader Shader::linear(Point p0, Point p1, std::vector<GradientStop> stops, SpreadMethod spread,
                      const Affine& transform) {
    Shader s;
    s.kind_ = Kind::Linear;
    s.p0_ = p0;
    s.p1_ = p1;
    s.stops_ = normalise(std::move(stops));
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
    s.stops_ = normalise(std::move(stops));
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
    // |p - c(t)| = r(t) with c(t) = f + t (c - f), r(t) = r0 + t (r1 - r0):
    // a t^2 - 2 b t + k = 0, a = |c - f|^2 - dr^2, b = (p - f).(c - f) + r0 dr, k = |p - f|^2 - r0^2.
    const double cdx = p1_.x - p0_.x, cdy = p1_.y - p0_.y, dr = r1_ - r0_;
    const double pdx = p.x - p0_.x, pdy = p.y - p0_.y;
    const double a = cdx * cdx + cdy * cdy - dr * dr;
    const double b = pdx * cdx + pdy * cdy + r0_ * dr;
    const double k = pdx * pdx + pdy * pdy - r0_ * r0_;
    auto radius_ok = [&](double u) { return r0_ + u * dr >= 0; };
    const double scale = cdx * cdx + cdy * cdy + dr * dr + r0_ * r0_ + 1e-300;
    if (std::fabs(a) <= 1e-9 * scale) {
        if (b == 0) {
            // Concentric circles of one radius: inside them takes the first stop.
            t = 0;
            return k <= 0;
        }
        t = k / (2 * b);
        return radius_ok(t);
    }
    const double disc = b * b - a * k;
    if (disc < 0) return false;
    const double sq = std::sqrt(disc);
    const double t1 = (b + sq) / a, t2 = (b - sq) / a;
    const double hi = std::max(t1, t2), lo = std::min(t1, t2);
    if (radius_ok(hi)) {
        t = hi;
        return true;
    }
    if (radius_ok(lo)) {
        t = lo;
        return true;
    }
    return false;
}

bool Shader::constant() const { return (kind_ == Kind::Linear && p0_ == p1_) || (kind_ == Kind::Radial && r1_ == 0); }

void Shader::color_at(double t, float rgba[4]) const {
    eval_stops(stops_, constant() ? 1.0 : spread_t(t, spread_), rgba);
}

namespace {

// The stops as the row loop reads them: offsets, 1 / (distance to the next offset) and the
// colours as floats in [0, 255].
struct RowStops {
    static constexpr std::size_t kMax = 32;  // more stops take Shader::color_at per pixel
    std::size_t n = 0;
    double offset[kMax], inv_span[kMax];
    float c[kMax][4];
    explicit RowStops(const std::vector<GradientStop>& stops) : n(stops.size()) {
        if (n > kMax) return;
        for (std::size_t i = 0; i < n; ++i) {
            const Color& k = stops[i].color;
            offset[i] = stops[i].offset;
            c[i][0] = k.r, c[i][1] = k.g, c[i][2] = k.b, c[i][3] = k.a;
            const double span = i + 1 < n ? stops[i + 1].offset - offset[i] : 0;
            inv_span[i] = span > 0 ? 1 / span : 0;
        }
    }
    // The premultiplied pixel at spread parameter u, alpha scaled by `op`.
    [[gnu::always_inline]] void put(double u, float op, std::uint8_t* o) const {
        float r, g, b, a;
        if (u <= offset[0]) {
            r = c[0][0], g = c[0][1], b = c[0][2], a = c[0][3];
        } else if (u >= offset[n - 1]) {
            r = c[n - 1][0], g = c[n - 1][1], b = c[n - 1][2], a = c[n - 1][3];
        } else {
            std::size_t i = 1;
            while (offset[i] <= u) ++i;  // offset[i - 1] <= u < offset[i]
            const float* c0 = c[i - 1];
            const float* c1 = c[i];
            const float w = inv_span[i - 1] > 0 ? static_cast<float>((u - offset[i - 1]) * inv_span[i - 1]) : 1.0f;
            r = c0[0] + (c1[0] - c0[0]) * w;
            g = c0[1] + (c1[1] - c0[1]) * w;
            b = c0[2] + (c1[2] - c0[2]) * w;
            a = c0[3] + (c1[3] - c0[3]) * w;
        }
        const float alpha = a * op;               // in [0, 255]
        const float k = alpha * (1.0f / 255.0f);  // premultiplies a channel in [0, 255]
        o[0] = static_cast<std::uint8_t>(r * k + 0.5f);
        o[1] = static_cast<std::uint8_t>(g * k + 0.5f);
        o[2] = static_cast<std::uint8_t>(b * k + 0.5f);
        o[3] = static_cast<std::uint8_t>(alpha + 0.5f);
    }
};

}  // namespace

// Every pixel's parameter is computed from its own position (the row's start plus x times the
// step along the row), so a pixel's colour does not depend on which span it was shaded in.
void Shader::shade_row(const Affine& inv, int x, int y, int length, double opacity, std::uint8_t* out) const {
    if (kind_ == Kind::Image) return shade_image_row(inv, x, y, length, opacity, out);
    const float op = static_cast<float>(std::clamp(opacity, 0.0, 1.0));
    const bool flat = constant();
    const RowStops table(stops_);
    auto put = [&](double t, std::uint8_t* o) __attribute__((always_inline)) {
        const double u = flat ? 1.0 : spread_t(t, spread_);
        if (table.n <= RowStops::kMax) return table.put(u, op, o);
        float c[4];
        eval_stops(stops_, u, c);
        const float a = c[3] * op;
        o[0] = static_cast<std::uint8_t>(c[0] * a * 255.0f + 0.5f);
        o[1] = static_cast<std::uint8_t>(c[1] * a * 255.0f + 0.5f);
        o[2] = static_cast<std::uint8_t>(c[2] * a * 255.0f + 0.5f);
        o[3] = static_cast<std::uint8_t>(a * 255.0f + 0.5f);
    };
    const Point row = inv.apply({0.5, y + 0.5});  // the centre of the row's pixel 0
    const double dx = p1_.x - p0_.x, dy = p1_.y - p0_.y, len2 = dx * dx + dy * dy;
    if (kind_ == Kind::Linear && len2 > 0) {
        // The parameter is affine along the row: t(X) = t(0) + X dt, no division per pixel.
        const double t0 = ((row.x - p0_.x) * dx + (row.y - p0_.y) * dy) / len2;
        const double dt = (inv.a * dx + inv.b * dy) / len2;
        for (int i = 0; i < length; ++i, out += 4) put(t0 + (x + i) * dt, out);
        return;
    }
    for (int i = 0; i < length; ++i, out += 4) {
        const double X = x + i;
        double t;
        if (!parameter({row.x + X * inv.a, row.y + X * inv.b}, t)) {
            out[0] = out[1] = out[2] = out[3] = 0;
            continue;
        }
        put(t, out);
    }
}

}  // namespace casteljau
