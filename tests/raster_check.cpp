// tests/raster_check.cpp: see raster_check.hpp.
#include "raster_check.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>

namespace casteljau::testing {

namespace {

class CheckingSink final : public SpanSink {
public:
    explicit CheckingSink(Rendered& r) : r_(r) {}
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        ++r_.rows_delivered;
        auto violate = [&](const char* what) {
            if (r_.contract_violation.empty()) {
                char buf[200];
                std::snprintf(buf, sizeof buf, "%s (row y=%d x=%d length=%d)", what, y, x, length);
                r_.contract_violation = buf;
            }
        };
        if (y <= last_y_) violate("rows not delivered in strictly increasing y");
        last_y_ = y;
        if (length < 0) return violate("negative span length");
        if (y < r_.clip.y0 || y >= r_.clip.y1 || x < r_.clip.x0 || x + length > r_.clip.x1)
            violate("span outside the clip rectangle");
        const IRect& w = r_.window;
        for (int i = 0; i < length; ++i) {
            const int px = x + i;
            if (px >= w.x0 && px < w.x1 && y >= w.y0 && y < w.y1) {
                r_.cov[static_cast<std::size_t>(y - w.y0) * w.width() + (px - w.x0)] = coverage[i];
            } else if (coverage[i] != 0) {
                ++r_.nonzero_outside_window;
            }
        }
    }

private:
    Rendered& r_;
    int last_y_ = INT_MIN;
};

}  // namespace

int Rendered::at(int x, int y) const {
    if (x < window.x0 || x >= window.x1 || y < window.y0 || y >= window.y1) return 0;
    return cov[static_cast<std::size_t>(y - window.y0) * window.width() + (x - window.x0)];
}

Rendered render(Rasterizer& r, const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip) {
    return render(r, path, m, opts, clip, clip);
}

Rendered render(Rasterizer& r, const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip,
                const IRect& window) {
    Rendered out;
    out.clip = clip;
    out.window = window;
    out.cov.assign(window.empty() ? 0 : static_cast<std::size_t>(window.width()) * window.height(), 0);
    CheckingSink sink(out);
    r.fill(path, m, opts, clip, sink);
    out.stats = r.last_stats();
    return out;
}

Comparison compare(const Rendered& actual, const ref::CoverageGrid& reference) {
    Comparison c;
    const IRect& a = actual.window;
    const IRect& b = reference.bounds;
    const IRect u{std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
    double sum = 0, sum_all = 0;
    bool first = true;
    for (int y = u.y0; y < u.y1; ++y) {
        for (int x = u.x0; x < u.x1; ++x) {
            const double rv = reference.at(x, y);
            const int av = actual.at(x, y);
            const double err = std::abs(av - 255.0 * rv);
            ++c.pixels;
            sum_all += err;
            const bool edge = (rv > 1e-12 && rv < 1 - 1e-12) || (av != 0 && av != 255) || err > 0.5;
            if (edge) {
                ++c.edge_pixels;
                sum += err;
            }
            if (err > 0.5 + 1e-3) ++c.misrounded;
            if (first || err > c.max_err) {
                first = false;
                c.max_err = err;
                c.worst_x = x;
                c.worst_y = y;
                c.worst_ref = rv;
                c.worst_actual = av;
            }
        }
    }
    c.mean_err = c.edge_pixels ? sum / static_cast<double>(c.edge_pixels) : 0.0;
    c.mean_all = c.pixels ? sum_all / static_cast<double>(c.pixels) : 0.0;
    return c;
}

std::string Comparison::text() const {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "max %.4f/255, mean %.4f/255 over all %zu pixels, mean %.4f/255 over %zu edge pixels "
                  "(%zu not correctly rounded); worst pixel (%d, %d): actual %d, reference %.6f (= %.3f/255)",
                  max_err, mean_all, pixels, mean_err, edge_pixels, misrounded, worst_x, worst_y, worst_actual,
                  worst_ref, worst_ref * 255.0);
    return buf;
}

Pixmap coverage_pixmap(const Rendered& r) {
    Pixmap pm(r.window.width(), r.window.height());
    for (int y = 0; y < r.window.height(); ++y)
        for (int x = 0; x < r.window.width(); ++x) {
            const std::uint8_t c = r.cov[static_cast<std::size_t>(y) * r.window.width() + x];
            pm.set_pixel(x, y, {c, c, c, 255});
        }
    return pm;
}

}  // namespace casteljau::testing

namespace casteljau::testing {

ref::Contour random_simple_polygon(std::mt19937& rng, Point c, double rmin, double rmax, int n) {
    // Angles: one per sector of 2 pi / n, jittered inside it, so consecutive angles differ by less
    // than pi: the polygon is star-shaped around c, hence simple.
    const double jitter = std::min(0.9, 0.5 * n - 1.05);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    ref::Contour out;
    for (int i = 0; i < n; ++i) {
        const double t = 2 * kPi * (i + jitter * u(rng)) / n;
        const double r = rmin + (rmax - rmin) * u(rng);
        out.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
    }
    return out;
}

ref::Contour random_polygon(std::mt19937& rng, const Rect& box, int n) {
    std::uniform_real_distribution<double> ux(box.x0, box.x1), uy(box.y0, box.y1);
    ref::Contour out;
    for (int i = 0; i < n; ++i) {
        const double x = ux(rng);
        out.push_back({x, uy(rng)});
    }
    return out;
}

ref::Contour star_polygon(Point c, double r, int p, int q, double rotation) {
    ref::Contour out;
    for (int i = 0; i < p; ++i) {
        const double t = rotation + 2 * kPi * static_cast<double>((i * q) % p) / p;
        out.push_back({c.x + r * std::sin(t), c.y - r * std::cos(t)});
    }
    return out;
}

ref::Contour regular_polygon(Point c, double r, int n, bool clockwise, double rotation) {
    ref::Contour out;
    for (int i = 0; i < n; ++i) {
        const double t = rotation + 2 * kPi * i / n * (clockwise ? 1 : -1);
        out.push_back({c.x + r * std::sin(t), c.y - r * std::cos(t)});
    }
    return out;
}

ref::Contour reversed(ref::Contour c) {
    std::reverse(c.begin(), c.end());
    return c;
}

}  // namespace casteljau::testing
