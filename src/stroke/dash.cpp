// Stroke stage: dashing of flattened contours (see include/casteljau/stroke.hpp for the semantics).
//
// A contour is walked segment by segment with the dash state (interval index, length left in it)
// carried across segments; every interval boundary that falls inside a segment starts or ends a
// dash there. On a closed contour the first dash is held back when the pattern starts "on", and is
// appended to the last dash when the pattern is still "on" where the contour wraps around.
#include <cmath>
#include <numeric>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "stroke/stroke_internal.hpp"

namespace casteljau::stroke_detail {

std::vector<double> effective_pattern(std::span<const double> dashes) {
    std::vector<double> p;
    bool negative = false;
    double total = 0;
    for (double d : dashes) {
        if (!std::isfinite(d)) throw Error(ErrorKind::InvalidData, "stroke: dash value is not a finite number");
        if (d < 0) negative = true;
        total += d;
    }
    if (dashes.empty() || negative || !(total > 0) || !std::isfinite(total)) return p;
    p.assign(dashes.begin(), dashes.end());
    if (p.size() % 2 == 1) p.insert(p.end(), dashes.begin(), dashes.end());
    return p;
}

namespace {

// The turn at every vertex of q, between segments v - 1 and v, for arc_factor: -1 where it is not
// known (not smooth, an open end, or past 1 radian).
void vertex_turns(std::span<const Point> q, std::span<const std::uint8_t> sm, bool closed, std::vector<double>& out) {
    const std::size_t n = q.size();
    out.assign(n, -1.0);
    auto seg = [&](std::size_t k) { return q[(k + 1) % n] - q[k]; };
    for (std::size_t v = 0; v < n; ++v) {
        if (!sm[v] || (!closed && (v == 0 || v + 1 >= n))) continue;
        const Vec u = seg((v + n - 1) % n), w = seg(v);
        const double a = std::atan2(std::abs(u.cross(w)), u.dot(w));
        if (std::isfinite(a) && a <= 1) out[v] = a;
    }
}

// How much longer than chord i of q the curve it stands for is (turns: vertex_turns of q). A chord
// between two smooth points spans an arc whose tangent turns by about the mean of the turns at its
// ends (on a circle, exactly the turn at each vertex), and an arc of angle phi is
// (phi / 2) / sin(phi / 2) times its chord:
// measured so, dashes keep their places along the curve to second order in the chords' turn
// instead of drifting by the chords' shortfall (a third of tolerance / radius). A chord with one
// smooth end takes that end's turn, one with none is a line. Turns past 1 radian say nothing of
// an arc and are not used.
double arc_factor(std::span<const double> turns, std::size_t i) {
    const std::size_t n = turns.size();
    const double ts = turns[i], te = turns[(i + 1) % n];
    const bool ks = ts >= 0, ke = te >= 0;
    const double phi = ks && ke ? 0.5 * (ts + te) : (ks ? ts : 0.0) + (ke ? te : 0.0);
    if (!(phi > 1e-4)) return 1;
    return 0.5 * phi / std::sin(0.5 * phi);
}

// A dash being built: its points and their smoothness.
struct Run {
    std::vector<Point> pts;
    std::vector<std::uint8_t> smooth;

    void push(Point p, std::uint8_t s) {
        pts.push_back(p);
        smooth.push_back(s);
    }
    void clear() {
        pts.clear();
        smooth.clear();
    }
    bool empty() const { return pts.empty(); }
    void swap(Run& o) {
        pts.swap(o.pts);
        smooth.swap(o.smooth);
    }
};

struct Dasher {
    std::span<const double> pattern;
    FlatContours& out;
    std::vector<Point>& dirs;
    Run cur;                    // the dash being built
    Run first;                  // closed contours: the dash that started at the contour's start
    std::vector<double> turns;  // the contour's vertex_turns
    std::size_t events = 0;
    std::size_t max_dashes;
    std::size_t max_points;

    // A dash's ends are cut across a chord (no curve direction known there) unless they are the
    // contour's own ends: `head` and `tail` are then the contour's.
    void emit(const Run& r, bool closed, Point dir, Vec head = {0, 0}, Vec tail = {0, 0}) {
        Polyline& o = out.poly;
        if (o.points.size() + r.pts.size() > max_points)
            throw Error(ErrorKind::Limit, "stroke: dashed path has too many points");
        o.points.insert(o.points.end(), r.pts.begin(), r.pts.end());
        out.smooth.insert(out.smooth.end(), r.smooth.begin(), r.smooth.end());
        o.contour_ends.push_back(static_cast<std::uint32_t>(o.points.size()));
        o.closed.push_back(closed);
        out.head.push_back(head);
        out.tail.push_back(tail);
        dirs.push_back(dir);
    }

    void contour(std::span<const Point> q, std::span<const std::uint8_t> sm, bool closed, double pos0, Vec head,
                 Vec tail) {
        const std::size_t n = pattern.size();
        // Find the interval holding pos0 (pos0 in [0, total)); a zero-length "on" interval at
        // position 0 is kept so that (0, d) patterns put a dot at the start.
        std::size_t di = 0;
        double pos = pos0;
        for (std::size_t guard = 0; pos > 0 && pos >= pattern[di] && guard < 2 * n; ++guard) {
            pos -= pattern[di];
            di = (di + 1) % n;
        }
        double rem = std::max(0.0, pattern[di] - pos);
        bool on = di % 2 == 0;
        const bool first_on = on && closed;
        bool crossed = false;  // an interval boundary was met on this contour
        bool holding_first = first_on;
        bool at_start = on && !closed;  // the dash being built starts at the contour's start

        cur.clear();
        first.clear();
        if (on) cur.push(q[0], closed ? sm[0] : 0);
        Point dir{0, 0}, first_dir{0, 0};

        vertex_turns(q, sm, closed, turns);
        const std::size_t nseg = closed ? q.size() : q.size() - 1;
        for (std::size_t i = 0; i < nseg; ++i) {
            const std::size_t j = (i + 1) % q.size();
            const Point a = q[i], b = q[j];
            const double chord = length_of(b - a);
            if (!(chord > 0)) continue;
            dir = (b - a) / chord;
            const double len = chord * arc_factor(turns, i);
            double t = 0;
            while (rem < len - t) {
                if (++events > 2 * max_dashes)
                    throw Error(ErrorKind::Limit, "stroke: dash pattern produces too many dashes");
                t += rem;
                const Point p = lerp(a, b, t / len);
                crossed = true;
                if (on) {
                    cur.push(p, 0);
                    if (holding_first) {
                        first.swap(cur);
                        first_dir = dir;
                        holding_first = false;
                    } else {
                        emit(cur, false, dir, at_start ? head : Vec{0, 0});
                    }
                    at_start = false;
                    cur.clear();
                } else {
                    cur.push(p, 0);
                }
                di = (di + 1) % n;
                rem = pattern[di];
                on = !on;
            }
            rem -= len - t;
            if (on) cur.push(b, j == 0 || (!closed && j + 1 == q.size()) ? 0 : sm[j]);
        }

        if (!crossed) {
            // The pattern never changed state on this contour.
            if (on) emit(cur, closed, dir, head, tail);
            return;
        }
        if (on) {
            if (first_on) {
                // The last dash runs through the wrap-around point into the first one.
                if (!first.empty()) {
                    cur.smooth.back() = sm[0];
                    cur.pts.insert(cur.pts.end(), first.pts.begin() + 1, first.pts.end());
                    cur.smooth.insert(cur.smooth.end(), first.smooth.begin() + 1, first.smooth.end());
                }
                first.clear();
            }
            emit(cur, false, dir, {0, 0}, closed ? Vec{0, 0} : tail);
        }
        if (!first.empty()) emit(first, false, first_dir);
    }
};

}  // namespace

void dash_polyline(const FlatContours& flat, std::span<const double> pattern, double offset, FlatContours& out,
                   std::vector<Point>& dirs) {
    const Polyline& in = flat.poly;
    out.clear();
    dirs.clear();
    const double total = std::accumulate(pattern.begin(), pattern.end(), 0.0);
    double pos = std::fmod(offset, total);
    if (pos < 0) pos += total;
    if (!(pos < total) || !(pos >= 0)) pos = 0;

    // Bound the work before doing it: each contour crosses at most (length / total + 1) periods.
    double periods = 0;
    std::size_t start = 0;
    for (std::size_t c = 0; c < in.contour_count(); ++c) {
        const std::size_t end = in.contour_ends[c];
        double len = 0;
        for (std::size_t i = start + 1; i < end; ++i) len += length_of(in.points[i] - in.points[i - 1]);
        if (in.closed[c] && end > start) len += length_of(in.points[start] - in.points[end - 1]);
        periods += len / total + 1;
        start = end;
    }
    const Limits lim = current_limits();
    const std::size_t max_dashes = lim.dashes;
    if (!(periods * static_cast<double>(pattern.size()) <= 2.0 * static_cast<double>(max_dashes)))
        throw Error(ErrorKind::Limit,
                    "stroke: dash pattern too fine for the path (more than " + std::to_string(max_dashes) + " dashes)");

    Dasher d{pattern, out, dirs, {}, {}, {}, 0, max_dashes, lim.flattened_segments};
    start = 0;
    for (std::size_t c = 0; c < in.contour_count(); ++c) {
        const std::size_t end = in.contour_ends[c];
        // A lone move (one point, not closed) has nothing to dash.
        if (end - start > 1 || (end > start && in.closed[c]))
            d.contour(std::span<const Point>(in.points.data() + start, end - start),
                      std::span<const std::uint8_t>(flat.smooth.data() + start, end - start), in.closed[c], pos,
                      flat.head[c], flat.tail[c]);
        start = end;
    }
}

}  // namespace casteljau::stroke_detail
