// Raster stage, overlap region: where plain accumulation of a polygon may be inexact
// (find_overlap_region in include/casteljau/raster.hpp).
//
// Plain accumulation gives each pixel the integral of the winding number over it, which is the
// covered area when every winding number met in the pixel lies in S = {0, 1} (or in {0, -1}).
// A segment is "good" when it meets no other segment (its two neighbours only at their shared
// vertex) and the winding numbers on both of its sides lie in S. A pixel that no bad segment
// reaches holds only good pieces, or none: every region of the plane that meets the pixel either
// borders one of its good pieces (so its winding number is in S) or covers the whole pixel (one
// winding number, and |integral| is the area). So accumulation is exact outside the boxes of the
// bad segments, and the overlap check need only look inside them.
//
// How:
//   1. Meetings: segments are paired on a uniform grid over their boxes; two segments meet when
//      they cross or an end point of one lies within a margin of the other's line (with boxes
//      that overlap, grown by the margin). Neighbours meet when they fold back along each other.
//      Both segments of a meeting are bad. The margin, 2^-30 of the path's extent, keeps every
//      decision below far above double rounding.
//   2. Sides: the good segments of a contour form arcs (maximal runs of them; a contour without
//      bad segments is one arc). Nothing meets an arc away from its ends, so the winding number
//      on each side is the same all along it: one ray from the midpoint of its steepest segment
//      to +x, counted over the other segments with the half-open rule, gives the number just
//      right of that segment, and the segment's own direction the one just left. A ray passing
//      within the margin of another segment's crossing, or an arc with no segment that is not
//      horizontal, makes the arc bad.
//   3. S is {0, 1} or {0, -1}, whichever holds more good segments; arcs with a side outside it
//      are bad.
// Cost: the grid (about twice as many cells as segments) and one ray per arc along one row of
// it, linear in the segments: a path whose grid would take more than kMaxEntriesPerSegment cell
// entries per segment (long segments across a fine grid), more than kMaxPairsPerSegment pairs of
// segments sharing a cell (stacked copies) or rays passing more than kMaxRayStepsPerSegment
// segments is left undecided, as is any path with curves.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "casteljau/raster.hpp"

namespace casteljau {

namespace {

constexpr double kMargin = 0x1p-30;                // of the path's extent
constexpr double kMaxExtent = 0x1p500;             // larger coordinates are left undecided
constexpr std::size_t kMaxCellsPerSegment = 64;    // grid cells
constexpr std::size_t kMaxEntriesPerSegment = 16;  // cell entries (a segment in each cell it reaches)
// Pairs of segments sharing a cell, and segments a ray passes, per segment: beyond, the segments
// crowd into few cells (stacked copies, a comb of arcs along one row) and the path is left
// undecided, so that the cost stays linear.
constexpr std::size_t kMaxPairsPerSegment = 64;
constexpr std::size_t kMaxRayStepsPerSegment = 64;

struct Seg {
    double x0, y0, x1, y1;
    std::uint32_t contour;
};

struct Contour {
    std::uint32_t first, count;  // its segments: segs[first .. first + count)
};

// Coordinates stay within kMaxExtent (Analysis::run), so squares cannot overflow.
inline double length(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }

inline double orient(double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

class Analysis {
public:
    explicit Analysis(const Path& path) { ok_ = collect(path); }
    OverlapRegion run();

private:
    bool collect(const Path& path);
    void close_contour(std::uint32_t first);
    bool build_grid();
    void find_meetings();
    bool meet(const Seg& a, const Seg& b) const;
    void check_neighbours();
    bool classify_arcs();  // false: the rays would cost more than kMaxRayStepsPerSegment
    void build_rows();     // row_start_ and row_segs_: the segments whose y range meets each grid row
    // Winding number just right of the midpoint of segment s, from the other segments; false
    // when a crossing lies within the margin of that point.
    bool winding_right_of(std::uint32_t s, int& w) const;
    int cell_x(double x) const { return std::clamp(static_cast<int>((x - gx0_) * inv_cell_), 0, gw_ - 1); }
    int cell_y(double y) const { return std::clamp(static_cast<int>((y - gy0_) * inv_cell_), 0, gh_ - 1); }

    bool ok_ = false;
    std::vector<Seg> segs_;
    std::vector<Contour> contours_;
    std::vector<Point> pts_;  // the current contour's points, repeats dropped
    Rect bounds_{INFINITY, INFINITY, -INFINITY, -INFINITY};
    double eps_ = 0;
    double gx0_ = 0, gy0_ = 0, inv_cell_ = 1;
    int gw_ = 1, gh_ = 1;
    std::vector<std::uint32_t> cell_start_;  // per cell (row-major) plus one: into cell_segs_
    std::vector<std::uint32_t> cell_segs_;
    std::vector<std::uint8_t> bad_;
    std::vector<Rect> boxes_;          // per segment, grown by the margin
    std::vector<std::uint32_t> next_;  // per segment, the next one along its contour
    std::vector<std::uint32_t> row_start_, row_segs_;
};

bool Analysis::collect(const Path& path) {
    const auto points = path.points();
    segs_.reserve(points.size() + path.verbs().size());
    std::size_t k = 0;
    for (Verb v : path.verbs()) {
        switch (v) {
            case Verb::Move:
                close_contour(static_cast<std::uint32_t>(segs_.size()));
                pts_.assign(1, points[k++]);
                break;
            case Verb::Line:
                if (pts_.empty()) pts_.push_back(Point{0, 0});
                if (!(points[k] == pts_.back())) pts_.push_back(points[k]);
                ++k;
                break;
            case Verb::Close: close_contour(static_cast<std::uint32_t>(segs_.size())); break;
            default: return false;  // curves: not decided here
        }
    }
    close_contour(static_cast<std::uint32_t>(segs_.size()));
    return true;
}

// The contour's segments, closing segment included (fill closes every contour).
void Analysis::close_contour(std::uint32_t first) {
    if (pts_.size() > 1 && pts_.front() == pts_.back()) pts_.pop_back();
    if (pts_.size() >= 2) {
        const auto c = static_cast<std::uint32_t>(contours_.size());
        for (std::size_t i = 0; i < pts_.size(); ++i) {
            const Point a = pts_[i], b = pts_[(i + 1) % pts_.size()];
            segs_.push_back({a.x, a.y, b.x, b.y, c});
            bounds_.x0 = std::min(bounds_.x0, a.x);
            bounds_.y0 = std::min(bounds_.y0, a.y);
            bounds_.x1 = std::max(bounds_.x1, a.x);
            bounds_.y1 = std::max(bounds_.y1, a.y);
        }
        contours_.push_back({first, static_cast<std::uint32_t>(pts_.size())});
    }
    pts_.clear();
}

bool Analysis::build_grid() {
    const double w = bounds_.x1 - bounds_.x0, h = bounds_.y1 - bounds_.y0;
    eps_ = kMargin * std::max({w, h, 1e-300});
    double len = 0;
    for (const Seg& s : segs_) len += std::abs(s.x1 - s.x0) + std::abs(s.y1 - s.y0);
    const double n = static_cast<double>(segs_.size());
    // Cells about twice a segment's size, so that a cell holds few segments wherever they cluster
    // (a country's coast, its islands across an ocean), and at most kMaxCellsPerSegment per
    // segment (clearing them costs less than pairing the segments of crowded cells).
    const double cell = std::max({2 * len / n, std::sqrt(w * h / (kMaxCellsPerSegment * n + 4096)), 1e-300});
    gx0_ = bounds_.x0;
    gy0_ = bounds_.y0;
    inv_cell_ = 1 / cell;
    gw_ = static_cast<int>(std::min(w * inv_cell_ + 1, 1e6));
    gh_ = static_cast<int>(std::min(h * inv_cell_ + 1, 1e6));
    const std::size_t cells = static_cast<std::size_t>(gw_) * static_cast<std::size_t>(gh_);
    if (!std::isfinite(inv_cell_) || cells > 2 * (kMaxCellsPerSegment * segs_.size() + 4096)) return false;
    cell_start_.assign(cells + 1, 0);
    auto each_cell = [&](const Seg& s, auto&& f) {
        const int cx0 = cell_x(std::min(s.x0, s.x1) - eps_), cx1 = cell_x(std::max(s.x0, s.x1) + eps_);
        const int cy0 = cell_y(std::min(s.y0, s.y1) - eps_), cy1 = cell_y(std::max(s.y0, s.y1) + eps_);
        for (int cy = cy0; cy <= cy1; ++cy)
            for (int cx = cx0; cx <= cx1; ++cx) f(static_cast<std::size_t>(cy) * static_cast<std::size_t>(gw_) + cx);
    };
    for (const Seg& s : segs_) each_cell(s, [&](std::size_t c) { ++cell_start_[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
    const std::size_t entries = cell_start_[cells];
    if (entries > kMaxEntriesPerSegment * segs_.size()) return false;
    std::size_t pairs = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        const std::size_t k = cell_start_[c + 1] - cell_start_[c];
        pairs += k * (k - 1) / 2 * (k > 1);
    }
    if (pairs > kMaxPairsPerSegment * segs_.size() + 4096) return false;
    cell_segs_.resize(entries);
    std::vector<std::uint32_t> at(cell_start_.begin(), cell_start_.end() - 1);
    for (std::uint32_t i = 0; i < segs_.size(); ++i)
        each_cell(segs_[i], [&](std::size_t c) { cell_segs_[at[c]++] = i; });
    return true;
}

// Two segments that are not neighbours, with boxes that overlap when grown by the margin, meet:
// they cross, or an end point of one lies within the margin of the other's line.
bool Analysis::meet(const Seg& a, const Seg& b) const {
    const double la = length(a.x1 - a.x0, a.y1 - a.y0), lb = length(b.x1 - b.x0, b.y1 - b.y0);
    const double d1 = orient(a.x0, a.y0, a.x1, a.y1, b.x0, b.y0), d2 = orient(a.x0, a.y0, a.x1, a.y1, b.x1, b.y1);
    const double d3 = orient(b.x0, b.y0, b.x1, b.y1, a.x0, a.y0), d4 = orient(b.x0, b.y0, b.x1, b.y1, a.x1, a.y1);
    if (std::abs(d1) <= eps_ * la || std::abs(d2) <= eps_ * la || std::abs(d3) <= eps_ * lb ||
        std::abs(d4) <= eps_ * lb)
        return true;
    return (d1 > 0) != (d2 > 0) && (d3 > 0) != (d4 > 0);
}

void Analysis::find_meetings() {
    boxes_.resize(segs_.size());
    next_.resize(segs_.size());
    for (const Contour& k : contours_)
        for (std::uint32_t i = 0; i < k.count; ++i) next_[k.first + i] = k.first + (i + 1) % k.count;
    for (std::size_t i = 0; i < segs_.size(); ++i) {
        const Seg& a = segs_[i];
        boxes_[i] = {std::min(a.x0, a.x1) - eps_, std::min(a.y0, a.y1) - eps_, std::max(a.x0, a.x1) + eps_,
                     std::max(a.y0, a.y1) + eps_};
    }
    const std::size_t cells = cell_start_.size() - 1;
    for (std::size_t c = 0; c < cells; ++c) {
        const std::uint32_t b = cell_start_[c], e = cell_start_[c + 1];
        if (e - b < 2) continue;
        const int cx = static_cast<int>(c % static_cast<std::size_t>(gw_)), cy = static_cast<int>(c / gw_);
        for (std::uint32_t i = b; i + 1 < e; ++i) {
            const std::uint32_t s = cell_segs_[i];
            const Rect bs = boxes_[s];
            const std::uint32_t sn = next_[s];
            for (std::uint32_t j = i + 1; j < e; ++j) {
                const std::uint32_t t = cell_segs_[j];
                if (t == sn || next_[t] == s) continue;  // neighbours: check_neighbours()
                const Rect& bt = boxes_[t];
                if (bs.x1 < bt.x0 || bt.x1 < bs.x0 || bs.y1 < bt.y0 || bt.y1 < bs.y0) continue;
                // A pair whose boxes share several cells is tested in one: the one holding the
                // low corner of their common box.
                if (cell_x(std::max(bs.x0, bt.x0)) != cx || cell_y(std::max(bs.y0, bt.y0)) != cy) continue;
                if ((!bad_[s] || !bad_[t]) && meet(segs_[s], segs_[t])) bad_[s] = bad_[t] = 1;
            }
        }
    }
}

// Neighbours a -> V -> b meet beyond V only when b folds back along a; a contour of two segments
// always does.
void Analysis::check_neighbours() {
    for (const Contour& k : contours_) {
        for (std::uint32_t i = 0; i < k.count; ++i) {
            const std::uint32_t s = k.first + i, t = k.first + (i + 1) % k.count;
            const Seg& a = segs_[s];
            const Seg& b = segs_[t];
            const double ux = a.x1 - a.x0, uy = a.y1 - a.y0, vx = b.x1 - b.x0, vy = b.y1 - b.y0;
            const double cross = ux * vy - uy * vx, dot = ux * vx + uy * vy;
            if (k.count < 3 || (dot < 0 && std::abs(cross) <= eps_ * (length(ux, uy) + length(vx, vy))))
                bad_[s] = bad_[t] = 1;
        }
    }
}

bool Analysis::winding_right_of(std::uint32_t s, int& w) const {
    const Seg& m = segs_[s];
    const double px = 0.5 * (m.x0 + m.x1), py = 0.5 * (m.y0 + m.y1);
    const int row = cell_y(py);
    w = 0;
    for (std::uint32_t i = row_start_[static_cast<std::size_t>(row)]; i < row_start_[static_cast<std::size_t>(row) + 1];
         ++i) {
        const std::uint32_t t = row_segs_[i];
        if (t == s) continue;
        const Seg& q = segs_[t];
        int dir;
        if (q.y0 <= py && py < q.y1)
            dir = 1;
        else if (q.y1 <= py && py < q.y0)
            dir = -1;
        else
            continue;
        const double x = q.x0 + (py - q.y0) * ((q.x1 - q.x0) / (q.y1 - q.y0));
        if (std::abs(x - px) <= eps_) return false;
        if (x > px) w += dir;
    }
    return true;
}

void Analysis::build_rows() {
    row_start_.assign(static_cast<std::size_t>(gh_) + 1, 0);
    for (const Seg& q : segs_) {
        if (q.y0 == q.y1) continue;
        for (int r = cell_y(std::min(q.y0, q.y1)), r1 = cell_y(std::max(q.y0, q.y1)); r <= r1; ++r)
            ++row_start_[static_cast<std::size_t>(r) + 1];
    }
    for (int r = 0; r < gh_; ++r)
        row_start_[static_cast<std::size_t>(r) + 1] += row_start_[static_cast<std::size_t>(r)];
    row_segs_.resize(row_start_.back());
    std::vector<std::uint32_t> at(row_start_.begin(), row_start_.end() - 1);
    for (std::uint32_t t = 0; t < segs_.size(); ++t) {
        const Seg& q = segs_[t];
        if (q.y0 == q.y1) continue;
        for (int r = cell_y(std::min(q.y0, q.y1)), r1 = cell_y(std::max(q.y0, q.y1)); r <= r1; ++r)
            row_segs_[at[static_cast<std::size_t>(r)]++] = t;
    }
}

bool Analysis::classify_arcs() {
    build_rows();
    struct Arc {
        std::uint32_t contour, start, count;  // segments start .. start + count - 1 (cyclic)
        int left, right;
        bool bad;
    };
    std::vector<Arc> arcs;
    for (std::uint32_t c = 0; c < contours_.size(); ++c) {
        const Contour& k = contours_[c];
        // Start after a bad segment, so that no arc wraps past the contour's start unseen.
        std::uint32_t start = 0;
        while (start < k.count && !bad_[k.first + start]) ++start;
        const bool whole = start == k.count;
        if (whole) start = 0;
        for (std::uint32_t i = 0; i < k.count;) {
            const std::uint32_t s = (start + i) % k.count;
            if (bad_[k.first + s]) {
                ++i;
                continue;
            }
            std::uint32_t n = 0;
            while (i + n < k.count && !bad_[k.first + (start + i + n) % k.count]) ++n;
            arcs.push_back({c, s, n, 0, 0, false});
            i += n;
        }
    }
    std::size_t positive = 0, negative = 0, steps = 0;
    const std::size_t budget = kMaxRayStepsPerSegment * segs_.size() + 4096;
    for (Arc& a : arcs) {
        const Contour& k = contours_[a.contour];
        std::uint32_t steep = 0;
        double best = 0;
        for (std::uint32_t i = 0; i < a.count; ++i) {
            const std::uint32_t s = k.first + (a.start + i) % k.count;
            const double dy = std::abs(segs_[s].y1 - segs_[s].y0);
            if (dy > best) {
                best = dy;
                steep = s;
            }
        }
        const auto row = static_cast<std::size_t>(cell_y(0.5 * (segs_[steep].y0 + segs_[steep].y1)));
        steps += row_start_[row + 1] - row_start_[row];
        if (steps > budget) return false;
        int right = 0;
        if (!(best > 0) || !winding_right_of(steep, right)) {
            a.bad = true;
            continue;
        }
        // Just left of the segment, the ray crosses it too: +1 where it runs down (y growing).
        a.right = right;
        a.left = right + (segs_[steep].y1 > segs_[steep].y0 ? 1 : -1);
        const int lo = std::min(a.left, a.right), hi = std::max(a.left, a.right);
        if (lo == 0 && hi == 1) positive += a.count;
        if (lo == -1 && hi == 0) negative += a.count;
    }
    const int lo_ok = positive >= negative ? 0 : -1;
    for (const Arc& a : arcs) {
        const bool in_s = std::min(a.left, a.right) == lo_ok && std::max(a.left, a.right) == lo_ok + 1;
        if (!a.bad && in_s) continue;
        const Contour& k = contours_[a.contour];
        for (std::uint32_t i = 0; i < a.count; ++i) bad_[k.first + (a.start + i) % k.count] = 1;
    }
    return true;
}

OverlapRegion Analysis::run() {
    OverlapRegion out;
    if (!ok_) return out;
    if (segs_.empty()) {
        out.topology = Topology::Simple;
        return out;
    }
    if (!(std::max({-bounds_.x0, bounds_.x1, -bounds_.y0, bounds_.y1}) < kMaxExtent) || !build_grid()) return out;
    bad_.assign(segs_.size(), 0);
    find_meetings();
    check_neighbours();
    if (!classify_arcs()) return out;
    for (std::size_t i = 0; i < segs_.size(); ++i) {
        if (!bad_[i]) continue;
        const Seg& s = segs_[i];
        out.boxes.push_back({std::min(s.x0, s.x1), std::min(s.y0, s.y1), std::max(s.x0, s.x1), std::max(s.y0, s.y1)});
    }
    out.topology = out.boxes.empty() ? Topology::Simple : Topology::Overlapping;
    return out;
}

}  // namespace

OverlapRegion find_overlap_region(const Path& path) { return Analysis(path).run(); }

}  // namespace casteljau
