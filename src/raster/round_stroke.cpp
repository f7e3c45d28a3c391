// Raster stage: coverage of the union of capsules (round strokes) by sample lines exact in x (see
// include/casteljau/round_stroke.hpp).
//
// Rows are swept top to bottom with an active list of the capsules whose vertical extent meets the
// row. On each sample line y = c every active capsule it crosses gives one interval (a capsule is
// convex, so the hull of the intervals of its two end discs and of its band is its whole section),
// the intervals are sorted and merged, and each merged interval adds its exact length inside every
// pixel it crosses, weighted by the line's share of the row: partial pixels at its two ends directly,
// the whole pixels between through a difference array. One prefix sum per row turns them into
// coverage.
//
// Error: on a band of height h the midpoint rule misses the integral of the covered length L(y) by
// at most h/2 times the total variation of L over the band (the half above the midpoint and the
// half below each differ from L(mid) by at most the variation on their side). Summed over the
// bands, a pixel is off by at most 1/(2 lines) times the variation of L over its height, and L
// varies only where the union's boundary moves sideways: by at most the horizontal extent of the
// boundary inside the pixel. A straight boundary crossing bands without ending in them adds
// nothing (L is linear there, which the midpoint integrates exactly).
#include "casteljau/round_stroke.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"

namespace casteljau {
namespace {

struct SweptSegment {
    double ax, ay, bx, by;  // the segment's ends
    double y0, y1;          // vertical extent, the radius included
    double x0;              // left end of the horizontal extent, the radius included
    // The band swept by the segment, on the line y = ay + dy, as x ranges:
    //   between its sides:  ax + side_slope dy -/+ side_half  (side_half infinite: horizontal segment)
    //   between its ends:   ax - end_slope dy + [end_lo, end_hi]
    // and for a vertical segment x in ax -/+ r while dy lies in [end_lo, end_hi].
    double side_slope = 0, side_half = INFINITY, end_slope = 0, end_lo = 0, end_hi = 0;
    bool band = false, vertical = false;
};

SweptSegment make_capsule(const LineSegment& s, double r) {
    SweptSegment k{
        s.a.x, s.a.y, s.b.x, s.b.y, std::min(s.a.y, s.b.y) - r, std::max(s.a.y, s.b.y) + r, std::min(s.a.x, s.b.x) - r};
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, len = std::hypot(dx, dy);
    if (!(len > 0) || !std::isfinite(len)) return k;  // a disc
    const double ux = dx / len, uy = dy / len;
    k.band = true;
    if (ux == 0) {
        k.vertical = true;
        k.end_lo = std::min(0.0, dy);
        k.end_hi = std::max(0.0, dy);
        return k;
    }
    if (uy != 0) {
        k.side_slope = ux / uy;
        k.side_half = r / std::abs(uy);
    }
    k.end_slope = uy / ux;
    k.end_lo = std::min(0.0, len / ux);
    k.end_hi = std::max(0.0, len / ux);
    return k;
}

// The interval [lo, hi] of x where the line y = c lies within r of capsule k; false when the line
// misses it. The capsule is convex, so its section is the hull of its two end discs' and its band's.
bool capsule_section(const SweptSegment& k, double r, double c, double& lo, double& hi) {
    lo = INFINITY;
    hi = -INFINITY;
    auto disc = [&](double px, double py) {
        const double d = c - py, s = r * r - d * d;
        if (s < 0) return;
        const double w = std::sqrt(s);
        lo = std::min(lo, px - w);
        hi = std::max(hi, px + w);
    };
    disc(k.ax, k.ay);
    disc(k.bx, k.by);
    if (k.band) {
        const double dy = c - k.ay;
        double l, h;
        if (k.vertical) {
            if (dy < k.end_lo || dy > k.end_hi) return lo < hi;
            l = k.ax - r;
            h = k.ax + r;
        } else {
            const double base = k.ax - k.end_slope * dy, mid = k.ax + k.side_slope * dy;
            l = std::max(base + k.end_lo, mid - k.side_half);
            h = std::min(base + k.end_hi, mid + k.side_half);
        }
        if (l <= h) {
            lo = std::min(lo, l);
            hi = std::max(hi, h);
        }
    }
    return lo < hi;
}

// The capsules that can reach `clip`, sorted by the top of their extent.
std::vector<SweptSegment> capsules_in(std::span<const LineSegment> segments, double r, const IRect& clip) {
    std::vector<SweptSegment> caps;
    caps.reserve(segments.size());
    for (const LineSegment& s : segments) {
        if (!s.a.is_finite() || !s.b.is_finite())
            throw Error(ErrorKind::InvalidArgument, "round_stroke_mask: segment coordinates must be finite");
        if (std::max(s.a.y, s.b.y) + r <= clip.y0 || std::min(s.a.y, s.b.y) - r >= clip.y1) continue;
        if (std::max(s.a.x, s.b.x) + r <= clip.x0 || std::min(s.a.x, s.b.x) - r >= clip.x1) continue;
        const SweptSegment k = make_capsule(s, r);
        caps.push_back(k);
    }
    std::sort(caps.begin(), caps.end(), [](const SweptSegment& p, const SweptSegment& q) { return p.y0 < q.y0; });
    return caps;
}

// One row's accumulators: partial pixels (`part`) and whole pixels as a difference array (`whole`),
// local x, and the range of pixels touched.
struct RowCoverage {
    std::vector<double> part, whole;
    int from, to = -1;

    explicit RowCoverage(int w)
        : part(static_cast<std::size_t>(w) + 2), whole(static_cast<std::size_t>(w) + 2), from(w + 1) {}

    // Adds `weight` times the length of [lo, hi] (local x, within [0, w]) inside every pixel.
    void add(double lo, double hi, double weight) {
        const int i0 = static_cast<int>(lo), i1 = static_cast<int>(hi);
        if (i0 == i1) {
            part[static_cast<std::size_t>(i0)] += (hi - lo) * weight;
        } else {
            part[static_cast<std::size_t>(i0)] += (i0 + 1 - lo) * weight;
            part[static_cast<std::size_t>(i1)] += (hi - i1) * weight;
            whole[static_cast<std::size_t>(i0) + 1] += weight;
            whole[static_cast<std::size_t>(i1)] -= weight;
        }
        from = std::min(from, i0);
        to = std::max(to, i1);
    }

    // Writes the touched pixels (of w) as 8-bit coverage into `out` and clears the accumulators.
    void emit(std::uint8_t* out, int w) {
        double run = 0;
        for (int i = from; i <= to; ++i) {
            const std::size_t k = static_cast<std::size_t>(i);
            run += whole[k];
            const double v = std::clamp(part[k] + run, 0.0, 1.0);
            if (i < w) out[k] = static_cast<std::uint8_t>(v * 255 + 0.5);
            part[k] = whole[k] = 0;
        }
        from = w + 1;
        to = -1;
    }
};

// Sorts a line's intervals by their left ends. They arrive nearly sorted (short capsules in order
// of their left ends), so insertion costs little; long capsules crossing each other can undo that,
// and past a few moves per interval a full sort takes over, so a line never costs the square of
// its intervals.
void sort_spans(std::vector<std::pair<double, double>>& spans) {
    const std::size_t limit = 4 * spans.size() + 64;
    std::size_t moves = 0;
    for (std::size_t a = 1; a < spans.size(); ++a) {
        const std::pair<double, double> v = spans[a];
        std::size_t b = a;
        for (; b > 0 && spans[b - 1].first > v.first; --b) spans[b] = spans[b - 1];
        spans[b] = v;
        moves += a - b;
        if (moves > limit) {
            std::sort(spans.begin(), spans.end());
            return;
        }
    }
}

}  // namespace

Mask round_stroke_mask(std::span<const LineSegment> segments, double radius, const IRect& clip, int lines_per_pixel) {
    Mask mask;
    round_stroke_mask(segments, radius, clip, mask, lines_per_pixel);
    return mask;
}

void round_stroke_mask(std::span<const LineSegment> segments, double radius, const IRect& clip, Mask& mask,
                       int lines_per_pixel) {
    if (!(radius > 0) || !std::isfinite(radius))
        throw Error(ErrorKind::InvalidArgument, "round_stroke_mask: the radius must be finite and > 0");
    if (lines_per_pixel < 1 || lines_per_pixel > kMaxRoundStrokeLines)
        throw Error(ErrorKind::InvalidArgument,
                    "round_stroke_mask: lines_per_pixel must be in [1, " + std::to_string(kMaxRoundStrokeLines) + "]");
    mask.bounds = {};
    mask.data.clear();
    if (clip.empty()) return;
    if (clip.width() > limits::kMaxCanvasDimension || clip.height() > limits::kMaxCanvasDimension)
        throw Error(ErrorKind::Limit, "round_stroke_mask: the clip exceeds " +
                                          std::to_string(limits::kMaxCanvasDimension) + " pixels per side");
    const std::vector<SweptSegment> caps = capsules_in(segments, radius, clip);
    mask.bounds = clip;
    const int w = clip.width();
    mask.data.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(clip.height()), 0);
    if (caps.empty()) return;
    RowCoverage row(w);
    std::vector<std::uint32_t> active;
    std::vector<std::pair<double, double>> spans;
    std::size_t next = 0;
    const double step = 1.0 / lines_per_pixel, x0 = clip.x0, x1 = clip.x1;
    for (int j = clip.y0; j < clip.y1; ++j) {
        std::erase_if(active, [&](std::uint32_t i) { return caps[i].y1 <= j; });
        // The active list stays in order of the capsules' left ends, so that each line's intervals
        // arrive nearly sorted.
        const std::size_t kept = active.size();
        for (; next < caps.size() && caps[next].y0 < j + 1; ++next) active.push_back(static_cast<std::uint32_t>(next));
        if (active.size() > kept) {
            auto left = [&](std::uint32_t a, std::uint32_t b) { return caps[a].x0 < caps[b].x0; };
            std::sort(active.begin() + static_cast<std::ptrdiff_t>(kept), active.end(), left);
            std::inplace_merge(active.begin(), active.begin() + static_cast<std::ptrdiff_t>(kept), active.end(), left);
        }
        if (active.empty()) {
            if (next == caps.size()) break;
            continue;
        }
        for (int s = 0; s < lines_per_pixel; ++s) {
            const double c = j + (s + 0.5) * step;
            spans.clear();
            for (std::uint32_t i : active) {
                const SweptSegment& k = caps[i];
                double lo, hi;
                if (c > k.y0 && c < k.y1 && capsule_section(k, radius, c, lo, hi)) spans.emplace_back(lo, hi);
            }
            sort_spans(spans);
            for (std::size_t a = 0; a < spans.size();) {
                double lo = spans[a].first, hi = spans[a].second;
                for (++a; a < spans.size() && spans[a].first <= hi; ++a) hi = std::max(hi, spans[a].second);
                lo = std::max(lo, x0);
                hi = std::min(hi, x1);
                if (hi > lo) row.add(lo - x0, hi - x0, step);
            }
        }
        row.emit(mask.data.data() + static_cast<std::size_t>(j - clip.y0) * static_cast<std::size_t>(w), w);
    }
}

}  // namespace casteljau
