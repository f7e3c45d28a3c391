// Map stage: cutting rings and lines at the antimeridian (the rule is in include/casteljau/map.hpp).
#include <cmath>
#include <span>
#include <vector>

#include "casteljau/map.hpp"

namespace casteljau {

namespace {

// Longitudes made continuous: each step is taken the short way round (|step| <= 180), by adding
// to each position the whole turns (multiples of 360) its steps so far took the short way; the
// positions before the first such step are copied exactly.
// Returns true when some step was changed (the ring or line crosses the antimeridian).
bool unwrap(std::span<const Point> in, std::vector<Point>& out) {
    out.clear();
    out.reserve(in.size() + 2);
    double turns = 0;
    bool crossed = false;
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (i > 0) {
            const double d = in[i].x - in[i - 1].x;
            if (d > 180) {
                turns -= 360;
                crossed = true;
            } else if (d < -180) {
                turns += 360;
                crossed = true;
            }
        }
        out.push_back({in[i].x + turns, in[i].y});
    }
    return crossed;
}

// Sutherland-Hodgman against one vertical half-plane: keep x >= bound (keep_right) or x <= bound.
void clip_x(const std::vector<Point>& in, double bound, bool keep_right, std::vector<Point>& out) {
    out.clear();
    const std::size_t n = in.size();
    if (n == 0) return;
    auto inside = [&](const Point& p) { return keep_right ? p.x >= bound : p.x <= bound; };
    for (std::size_t i = 0; i < n; ++i) {
        const Point& a = in[i];
        const Point& b = in[(i + 1) % n];
        const bool ia = inside(a), ib = inside(b);
        if (ia) out.push_back(a);
        if (ia != ib) {
            const double t = (bound - a.x) / (b.x - a.x);
            out.push_back({bound, a.y + (b.y - a.y) * t});
        }
    }
}

double signed_area2(const std::vector<Point>& r) {
    double s = 0;
    for (std::size_t i = 0, n = r.size(); i < n; ++i) {
        const Point& a = r[i];
        const Point& b = r[(i + 1) % n];
        s += a.x * b.y - b.x * a.y;
    }
    return s;
}

}  // namespace

void split_ring_at_antimeridian(std::span<const Point> ring, std::vector<std::vector<Point>>& out) {
    if (ring.size() < 3) return;
    std::vector<Point> u;
    const bool crossed = unwrap(ring, u);
    // The ring is closed (last == first); work without the repeated position.
    if (u.size() > 1 && ring.front() == ring.back()) u.pop_back();
    if (!crossed) {
        out.push_back(std::move(u));
        return;
    }
    // Net turn around the globe: the unwrapped end sits k*360 degrees from the start.
    const Point first = u.front();
    double net = 0;
    {
        const std::size_t n = ring.size();
        double d = ring[0].x - ring[n - 1].x;
        if (d > 180)
            d -= 360;
        else if (d < -180)
            d += 360;
        net = (u.back().x + d) - first.x;  // closing step included
    }
    if (std::fabs(net) > 180) {
        // Winds around a pole: close it along the pole on the side of its mean latitude.
        double mean = 0;
        for (const Point& p : u) mean += p.y;
        const double pole = mean < 0 ? -90.0 : 90.0;
        const Point last = u.back();
        double d = ring[0].x - ring[ring.size() - 1].x;
        if (d > 180)
            d -= 360;
        else if (d < -180)
            d += 360;
        const double end_x = last.x + d;  // where the ring would return, k*360 away from its start
        u.push_back({end_x, first.y});
        u.push_back({end_x, pole});
        u.push_back({first.x, pole});
    }
    double xmin = INFINITY, xmax = -INFINITY;
    for (const Point& p : u) {
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
    }
    const int k0 = static_cast<int>(std::floor((xmin + 180.0) / 360.0));
    const int k1 = static_cast<int>(std::ceil((xmax + 180.0) / 360.0)) - 1;
    std::vector<Point> a, b;
    for (int k = k0; k <= k1; ++k) {
        const double lo = k * 360.0 - 180.0, hi = lo + 360.0;
        clip_x(u, lo, true, a);
        clip_x(a, hi, false, b);
        if (b.size() < 3 || signed_area2(b) == 0) continue;
        for (Point& p : b) p.x -= k * 360.0;
        out.push_back(b);
    }
}

void split_line_at_antimeridian(std::span<const Point> line, std::vector<std::vector<Point>>& out) {
    if (line.empty()) return;
    std::vector<Point> u;
    if (!unwrap(line, u)) {
        out.emplace_back(line.begin(), line.end());
        return;
    }
    auto band_of = [](double x) { return static_cast<int>(std::floor((x + 180.0) / 360.0)); };
    std::vector<Point> piece;
    int k = band_of(u[0].x);
    piece.push_back({u[0].x - k * 360.0, u[0].y});
    for (std::size_t i = 1; i < u.size(); ++i) {
        const Point a = u[i - 1], b = u[i];
        int kb = band_of(b.x);
        while (kb != k) {
            // Leave band k through its east (b east of a) or west edge.
            const double edge = b.x > a.x ? k * 360.0 + 180.0 : k * 360.0 - 180.0;
            const double t = (edge - a.x) / (b.x - a.x);
            const double y = a.y + (b.y - a.y) * t;
            piece.push_back({edge - k * 360.0, y});
            if (piece.size() >= 2) out.push_back(piece);
            piece.clear();
            k += b.x > a.x ? 1 : -1;
            piece.push_back({edge - k * 360.0, y});
        }
        piece.push_back({b.x - k * 360.0, b.y});
    }
    if (piece.size() >= 2) out.push_back(std::move(piece));
}

}  // namespace casteljau
