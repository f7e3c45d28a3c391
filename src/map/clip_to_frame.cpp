// Map stage: cutting rings and lines to a rectangle around the image (src/map/clip_to_frame.hpp).
#include "map/clip_to_frame.hpp"

#include <algorithm>
#include <utility>

namespace casteljau::map_detail {

namespace {

bool less(Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// Where the step a-b crosses the line x = v (vertical) or y = v, from its lesser end.
Point crossing(Point a, Point b, double v, bool vertical) {
    if (less(b, a)) std::swap(a, b);
    if (vertical) {
        const double t = (v - a.x) / (b.x - a.x);
        return {v, a.y + (b.y - a.y) * t};
    }
    const double t = (v - a.y) / (b.y - a.y);
    return {a.x + (b.x - a.x) * t, v};
}

// One Sutherland-Hodgman pass: keeps the side of the line x = v (vertical) or y = v where
// coordinate >= v (keep_above) or <= v.
void clip_side(const std::vector<Point>& in, double v, bool vertical, bool keep_above, std::vector<Point>& out) {
    out.clear();
    const std::size_t n = in.size();
    auto inside_of = [&](Point p) {
        const double c = vertical ? p.x : p.y;
        return keep_above ? c >= v : c <= v;
    };
    for (std::size_t i = 0; i < n; ++i) {
        const Point a = in[i], b = in[(i + 1) % n];
        const bool ia = inside_of(a), ib = inside_of(b);
        if (ia) out.push_back(a);
        if (ia != ib) out.push_back(crossing(a, b, v, vertical));
    }
}

}  // namespace

bool inside(std::span<const Point> pts, const Rect& r) {
    for (Point p : pts)
        if (!(p.x >= r.x0 && p.x <= r.x1 && p.y >= r.y0 && p.y <= r.y1)) return false;
    return true;
}

void clip_ring(std::span<const Point> ring, const Rect& r, std::vector<Point>& out) {
    std::vector<Point> a(ring.begin(), ring.end()), b;
    clip_side(a, r.x0, true, true, b);
    clip_side(b, r.x1, true, false, a);
    clip_side(a, r.y0, false, true, b);
    clip_side(b, r.y1, false, false, out);
}

void clip_line(std::span<const Point> line, const Rect& r, Path& out) {
    bool open = false;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const Point a = line[i], b = line[i + 1];
        const bool reaches = std::max(a.x, b.x) >= r.x0 && std::min(a.x, b.x) <= r.x1 && std::max(a.y, b.y) >= r.y0 &&
                             std::min(a.y, b.y) <= r.y1;
        if (!reaches) {
            open = false;
            continue;
        }
        if (!open) out.move_to(a);
        out.line_to(b);
        open = true;
    }
}

}  // namespace casteljau::map_detail
