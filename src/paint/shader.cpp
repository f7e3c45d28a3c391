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

void Shader::color_at(double t, float rgba[4]) const {
    const bool constant = (kind_ == Kind::Linear && p0_ == p1_) || (kind_ == Kind::Radial && r1_ == 0);
    const double u = constant ? 1.0 : spread_t(t, spread_);
    auto put = [&](const Color& c) {
        rgba[0] = c.r / 255.0f;
        rgba[1] = c.g / 255.0f;
        rgba[2] = c.b / 255.0f;
        rgba[3] = c.a / 255.0f;
    };
    if (u <= stops_.front().offset) return put(stops_.front().color);
    if (u >= stops_.back().offset) return put(stops_.back().color);
    std::size_t i = 1;
    while (i < stops_.size() && stops_[i].offset <= u) ++i;  // stops_[i - 1].offset <= u < stops_[i].offset
    const GradientStop& s0 = stops_[i - 1];
    const GradientStop& s1 = stops_[i];
    const double span = s1.offset - s0.offset;
    const float w = span > 0 ? static_cast<float>((u - s0.offset) / span) : 1.0f;
    rgba[0] = (s0.color.r + (s1.color.r - s0.color.r) * w) / 255.0f;
    rgba[1] = (s0.color.g + (s1.color.g - s0.color.g) * w) / 255.0f;
    rgba[2] = (s0.color.b + (s1.color.b - s0.color.b) * w) / 255.0f;
    rgba[3] = (s0.color.a + (s1.color.a - s0.color.a) * w) / 255.0f;
}

void Shader::shade_row(const Affine& inv, int x, int y, int length, double opacity, std::uint8_t* out) const {
    if (kind_ == Kind::Image) return shade_image_row(inv, x, y, length, opacity, out);
    const float op = static_cast<float>(std::clamp(opacity, 0.0, 1.0));
    auto put = [op](double t, std::uint8_t* o, const Shader& s) {
        float c[4];
        s.color_at(t, c);
        const float a = c[3] * op;
        o[0] = static_cast<std::uint8_t>(c[0] * a * 255.0f + 0.5f);
        o[1] = static_cast<std::uint8_t>(c[1] * a * 255.0f + 0.5f);
        o[2] = static_cast<std::uint8_t>(c[2] * a * 255.0f + 0.5f);
        o[3] = static_cast<std::uint8_t>(a * 255.0f + 0.5f);
    };
    Point p = inv.apply({x + 0.5, y + 0.5});
    const double dx = p1_.x - p0_.x, dy = p1_.y - p0_.y, len2 = dx * dx + dy * dy;
    if (kind_ == Kind::Linear && len2 > 0) {
        // The parameter is affine along the row: t(i) = t0 + i dt, no division per pixel.
        const double t0 = ((p.x - p0_.x) * dx + (p.y - p0_.y) * dy) / len2;
        const double dt = (inv.a * dx + inv.b * dy) / len2;
        for (int i = 0; i < length; ++i, out += 4) put(t0 + i * dt, out, *this);
        return;
    }
    for (int i = 0; i < length; ++i, out += 4, p.x += inv.a, p.y += inv.b) {
        double t;
        if (!parameter(p, t)) {
            out[0] = out[1] = out[2] = out[3] = 0;
            continue;
        }
        put(t, out, *this);
    }
}

}  // namespace casteljau
