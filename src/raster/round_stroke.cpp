// Raster stage: coverage of the union of capsules (round strokes) by sample lines exact in x (see
// include/casteljau/round_stroke.hpp).
//
// Rows are swept top to bottom with an active list of the capsules whose vertical extent meets the
// row, in order of their left ends. Each active capsule gives one interval on every sample line
// y = c of the row it crosses (a capsule is convex, so the hull of the intervals of its two end discs
// and of its band is its whole section; capsule_section.hpp computes a run of lines at once), and
// each line keeps the union of its intervals as they arrive (LineUnion). Each interval of the union
// adds its exact length inside every pixel it crosses (RowCoverage: one cell update per end) as
// soon as no capsule still to come can reach it, or at the end of the row, and one running sum
// per row, times the lines' common weight, turns the cells into coverage, handed to a SpanSink in
// runs of the blocks the intervals reached. A capsule's section form is built once, when its first
// row comes. The lines are kept in float for clips near x = 0 (kFloatSweepSide), each segment cut
// to a strip of x there first (in_float_strip), and in double for others.
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
#include <bit>
#include <cmath>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "raster/capsule_section.hpp"

namespace casteljau {
namespace {

using raster::SweptCapsule;

// Capsules ahead whose segments the sweep fetches before it builds them.
constexpr std::size_t kFetchAhead = 8;

// Clips whose x, with the radius and a pixel around them, stay within this many pixels of 0 are swept
// in float (in_float_strip); others in double.
constexpr double kFloatSweepSide = 8192;

// The band's parameters straight from the segment's differences (ux / uy = dx / dy and so on), so
// that the square root of its length holds up only the half-width: two divisions, not five.
SweptCapsule make_capsule(const LineSegment& s, double r) {
    SweptCapsule k{s.a.x, s.a.y, s.b.x, s.b.y, std::min(s.a.y, s.b.y) - r, std::max(s.a.y, s.b.y) + r};
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, len2 = dx * dx + dy * dy;
    if (!(len2 > 0) || !std::isfinite(len2)) return k;  // a disc
    k.band = true;
    if (dx == 0) {
        k.vertical = true;
        k.end_lo = std::min(0.0, dy);
        k.end_hi = std::max(0.0, dy);
        return k;
    }
    const double inv_dx = 1 / dx;
    if (dy != 0) {
        const double inv_dy = 1 / dy;
        k.side_slope = dx * inv_dy;
        k.side_half = r * std::sqrt(len2) * std::abs(inv_dy);
    }
    k.end_slope = dy * inv_dx;
    k.end_lo = std::min(0.0, len2 * inv_dx);
    k.end_hi = std::max(0.0, len2 * inv_dx);
    return k;
}

// Segment s cut to the strip |x| <= kFloatSweepSide, for a sweep in float: its coordinates keep
// 2^-10 px there (y is taken from each row's top, capsule_section.hpp). The clip and the radius
// and a pixel around it lie inside the strip, and the points within the radius of s there are
// within it of the part kept. A segment that misses the strip becomes a point on its left edge,
// whose disc cannot reach the clip. The cut depends on s alone, not on the clip, so every clip
// (a band of an image, or the whole) sweeps the same capsules.
LineSegment in_float_strip(const LineSegment& s) {
    constexpr double lo = -kFloatSweepSide, hi = kFloatSweepSide;
    const Point a = s.a, b = s.b;
    if (a.x >= lo && a.x <= hi && b.x >= lo && b.x <= hi) return s;
    if ((a.x < lo && b.x < lo) || (a.x > hi && b.x > hi)) return {{lo, a.y}, {lo, a.y}};
    // The parameters [t0, t1] of a + t (b - a) inside the strip (b.x != a.x here).
    const double dx = b.x - a.x, ta = (lo - a.x) / dx, tb = (hi - a.x) / dx;
    const double t0 = std::max(0.0, std::min(ta, tb)), t1 = std::min(1.0, std::max(ta, tb));
    auto at = [&](double t) { return Point{std::clamp(a.x + dx * t, lo, hi), a.y + (b.y - a.y) * t}; };
    return {t0 > 0 ? at(t0) : a, t1 < 1 ? at(t1) : b};
}

// A segment that can reach the clip: its extent, the radius included, and its index. The sweep
// keeps these small records and builds a capsule's section form only for the rows it crosses.
struct Extent {
    double y0, y1, x0;
    std::uint32_t segment;
};

// The segments that can reach `clip`, in order of the pixel row where their extent begins (a
// counting sort: two passes over the segments), and in each row in order of their left ends.
std::vector<Extent> extents_in(std::span<const LineSegment> segments, double r, const IRect& clip) {
    if (segments.size() > UINT32_MAX) throw Error(ErrorKind::Limit, "round_stroke_mask: more than 2^32 - 1 segments");
    // Calls each(first row, extent) for every segment reaching the clip, rows relative to clip.y0.
    auto for_each = [&](auto&& each) {
        for (std::size_t i = 0; i < segments.size(); ++i) {
            const LineSegment& s = segments[i];
            if (!s.a.is_finite() || !s.b.is_finite())
                throw Error(ErrorKind::InvalidArgument, "round_stroke_mask: segment coordinates must be finite");
            const double y0 = std::min(s.a.y, s.b.y) - r, y1 = std::max(s.a.y, s.b.y) + r;
            const double x0 = std::min(s.a.x, s.b.x) - r;
            if (y1 <= clip.y0 || y0 >= clip.y1 || std::max(s.a.x, s.b.x) + r <= clip.x0 || x0 >= clip.x1) continue;
            const double row = std::clamp(std::floor(y0), double(clip.y0), double(clip.y1 - 1)) - clip.y0;
            each(static_cast<std::size_t>(row), Extent{y0, y1, x0, static_cast<std::uint32_t>(i)});
        }
    };
    std::vector<std::size_t> start(static_cast<std::size_t>(clip.height()) + 1, 0);
    for_each([&](std::size_t row, const Extent&) { ++start[row + 1]; });
    for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
    std::vector<Extent> out(start.back());
    for_each([&](std::size_t row, const Extent& e) { out[start[row]++] = e; });
    // start[row] is now where the next row begins.
    auto left = [](const Extent& a, const Extent& b) { return a.x0 < b.x0; };
    for (std::size_t row = 0, begin = 0; row + 1 < start.size(); begin = start[row++])
        std::sort(out.begin() + static_cast<std::ptrdiff_t>(begin),
                  out.begin() + static_cast<std::ptrdiff_t>(start[row]), left);
    return out;
}

// One row's accumulators, local x, as cells: an interval end at x = i + f (pixel i, 0 <= f < 1)
// that starts coverage (sign +1) or ends it (-1) adds the sign to cell i's `cover` and sign times f
// to its `area`, so that the covered length in pixel i is the sum of `cover` over cells 0..i minus
// `area` of cell i; times the lines' common weight, its coverage. One cell per end: two updates per
// interval. A map's row is mostly empty, so emit() visits only the blocks of kBlock pixels that an
// interval reached (from its first pixel to its last), found by scanning a bit per block: between
// them the running sum of `cover` is zero (whole numbers, summed exactly) and the pixels stay 0.
class RowCoverage {
public:
    explicit RowCoverage(int w)
        : cells_(static_cast<std::size_t>(w) + 2),
          touched_(static_cast<std::size_t>((w + 2) / kBlock / 64 + 1), 0),
          out_(static_cast<std::size_t>(w)),
          from_(w + 1) {}

    // Adds the length of [lo, hi] (local x, within [0, w]) inside every pixel.
    void add(double lo, double hi) {
        const int i0 = static_cast<int>(lo), i1 = static_cast<int>(hi);
        Cell& a = cells_[static_cast<std::size_t>(i0)];
        a.cover += 1;
        a.area += lo - i0;
        Cell& b = cells_[static_cast<std::size_t>(i1)];
        b.cover -= 1;
        b.area -= hi - i1;
        // Both ends are >= 0: unsigned shifts, without the signed division's rounding fix.
        const unsigned k0 = static_cast<unsigned>(i0) / unsigned{kBlock},
                       k1 = static_cast<unsigned>(i1) / unsigned{kBlock};
        touched_[k0 / 64] |= std::uint64_t{1} << (k0 % 64);
        for (unsigned k = k0 + 1; k <= k1; ++k) touched_[k / 64] |= std::uint64_t{1} << (k % 64);
        from_ = std::min(from_, i0);
        to_ = std::max(to_, i1);
    }

    // Adds a run of summed lengths (capsule_section.hpp) whose pixel x is origin + run.x.
    void add_run(const raster::SettledRun& run, int origin) {
        const int p0 = run.x - origin;
        for (int k = 0; k < run.count; ++k)
            cells_[static_cast<std::size_t>(p0 + k)].area -= run.units[k] * raster::kSettledUnit;
        const unsigned k0 = static_cast<unsigned>(p0) / unsigned{kBlock},
                       k1 = static_cast<unsigned>(p0 + run.count - 1) / unsigned{kBlock};
        for (unsigned k = k0; k <= k1; ++k) touched_[k / 64] |= std::uint64_t{1} << (k % 64);
        from_ = std::min(from_, p0);
        to_ = std::max(to_, p0 + run.count - 1);
    }

    // Hands `sink` row y's touched pixels (of w, from x0), each covered length times `weight` as
    // 8-bit coverage, one run of touched blocks at a time, and clears the accumulators.
    void emit(double weight, int y, int x0, int w, SpanSink& sink) {
        double run = 0;
        int start = -1, end = -1;  // the run being written: pixels [start, end)
        const int last_pixel = std::min(to_, w - 1);
        for (int word_index = from_ / kBlock / 64; word_index <= to_ / kBlock / 64; ++word_index) {
            std::uint64_t word = std::exchange(touched_[static_cast<std::size_t>(word_index)], 0);
            for (; word != 0; word &= word - 1) {  // the touched blocks in order
                const int k = word_index * 64 + std::countr_zero(word);
                const int first = std::max(from_, k * kBlock), last = std::min(last_pixel, k * kBlock + kBlock - 1);
                if (first > last) continue;  // only cell w: ends at the right edge, which no pixel reads
                if (start >= 0 && first != end) {
                    sink.row(y, x0 + start, end - start, out_.data() + start);
                    start = -1;
                }
                if (start < 0) start = first;
                for (int i = first; i <= last; ++i) {
                    Cell& c = cells_[static_cast<std::size_t>(i)];
                    run += c.cover;
                    const double v = std::clamp((run - c.area) * weight, 0.0, 1.0);
                    out_[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v * 255 + 0.5);
                    c = Cell{};
                }
                end = last + 1;
            }
        }
        if (start >= 0) sink.row(y, x0 + start, end - start, out_.data() + start);
        from_ = w + 1;
        to_ = -1;
    }

private:
    static constexpr int kBlock = 16;
    struct Cell {
        double cover = 0, area = 0;
    };
    std::vector<Cell> cells_;
    std::vector<std::uint64_t> touched_;  // one bit per block
    std::vector<std::uint8_t> out_;       // the row's coverage, valid in the runs handed out
    int from_, to_ = -1;
};

// The union of the intervals on one sample line, built as they arrive. They arrive nearly in order
// of their left ends (capsules in order of theirs), so most meet the line's open interval (the
// rightmost so far) and merge with it, which capsule_sections does; one right of it closes it and
// opens another (capsule_sections too), and the closed one goes to the row's coverage at once when
// it ends left of the capsule's left end (no later capsule reaches it), else to the closed list;
// one between the last closed interval and the open one is kept in its place. Only one reaching
// back over closed intervals (long capsules crossing each other) is kept as it comes, and then the
// line is sorted and merged once at the end, so a line never costs the square of its intervals.
class LineUnion {
public:
    void clear() {
        closed_.clear();
        sorted_ = true;
    }

    // Whether the closed intervals are still in order (else they are sorted once at the end).
    bool in_order() const { return sorted_; }

    // The open interval [lo, hi], closed by capsule_sections. No interval still to come starts left
    // of `settled_below`: one ending left of it, with the closed ones in order (so none overlaps it),
    // is final and goes to settle(lo, hi) instead of the closed list.
    template <class Settle>
    void close(double lo, double hi, double settled_below, const Settle& settle) {
        if (sorted_ && hi < settled_below)
            settle(lo, hi);
        else
            closed_.emplace_back(lo, hi);
    }

    // Interval [lo, hi], which capsule_sections left: it meets the open interval [open_lo, open_hi]
    // or lies left of it, and reaches where the closed intervals end (closed_hi) or the line is
    // no longer in order.
    // (Real: the lines' type, float or double; every value here is one of them, so the
    // conversions are exact.)
    template <class Real>
    void add(double lo, double hi, Real& open_lo, Real& open_hi, Real& closed_hi) {
        if (!sorted_) {
            closed_.emplace_back(lo, hi);
        } else if (hi >= open_lo) {  // meets the open interval and reaches closed ones: merge them
            double merged_lo = std::min<double>(open_lo, lo);
            open_hi = static_cast<Real>(std::max<double>(open_hi, hi));
            while (!closed_.empty() && closed_.back().second >= merged_lo) {
                merged_lo = std::min(merged_lo, closed_.back().first);
                closed_.pop_back();
            }
            open_lo = static_cast<Real>(merged_lo);
            closed_hi = static_cast<Real>(closed_.empty() ? -INFINITY : closed_.back().second);
        } else {
            insert_closed(lo, hi);
            closed_hi = static_cast<Real>(closed_.back().second);
        }
    }

    // The disjoint intervals of the union with the open one, in order; intervals that touch are one.
    const std::vector<std::pair<double, double>>& merged(double open_lo, double open_hi) {
        if (open_lo <= open_hi) closed_.emplace_back(open_lo, open_hi);
        if (sorted_) return closed_;
        std::sort(closed_.begin(), closed_.end());
        std::size_t out = 0;
        for (std::size_t a = 0; a < closed_.size(); ++out) {
            double lo = closed_[a].first, hi = closed_[a].second;
            for (++a; a < closed_.size() && closed_[a].first <= hi; ++a) hi = std::max(hi, closed_[a].second);
            closed_[out] = {lo, hi};
        }
        closed_.resize(out);
        sorted_ = true;
        return closed_;
    }

private:
    // [lo, hi] among the closed intervals, merged with those it meets, when its place is a few
    // intervals from the end; else kept as it comes, for the sort at the end.
    void insert_closed(double lo, double hi) {
        constexpr std::size_t kMaxSteps = 8;
        std::size_t k = closed_.size();
        while (k > 0 && closed_[k - 1].first > hi && closed_.size() - k < kMaxSteps) --k;
        if (k > 0 && closed_[k - 1].first > hi) {
            closed_.emplace_back(lo, hi);
            sorted_ = false;
            return;
        }
        std::size_t end = k;  // closed_[k, end) meet [lo, hi]
        while (k > 0 && closed_[k - 1].second >= lo) --k;
        if (k == end) {
            closed_.insert(closed_.begin() + static_cast<std::ptrdiff_t>(k), {lo, hi});
            return;
        }
        closed_[k] = {std::min(lo, closed_[k].first), std::max(hi, closed_[end - 1].second)};
        closed_.erase(closed_.begin() + static_cast<std::ptrdiff_t>(k) + 1,
                      closed_.begin() + static_cast<std::ptrdiff_t>(end));
    }

    std::vector<std::pair<double, double>> closed_;
    bool sorted_ = true;
};

// The sample lines of one pixel row: each line's union (LineUnion) with its open interval and the
// end of its closed ones kept in arrays, as capsule_sections reads and folds them, in Real (float
// or double).
template <class Real>
class RowLines {
public:
    RowLines(int lines, double r) : lines_(static_cast<std::size_t>(lines)) {
        static_assert(raster::kMaxSectionLines >= kMaxRoundStrokeLines);
        for (std::vector<Real>* v : {&lo_, &hi_, &open_lo_, &open_hi_, &closed_hi_, &settle_limit_})
            v->resize(raster::kMaxSectionLines + raster::kSectionPadding);
        runs_.resize(kMaxRuns);
        st_.lines = lines;
        st_.r = r;
        st_.open_lo = open_lo_.data();
        st_.open_hi = open_hi_.data();
        st_.closed_hi = closed_hi_.data();
        st_.settle_limit = settle_limit_.data();
        st_.lo = lo_.data();
        st_.hi = hi_.data();
        st_.left_bits = left_bits_;
        st_.closed_bits = closed_bits_;
        st_.margin = kRoundingMargin;
        st_.runs = runs_.data();
        st_.max_runs = kMaxRuns;
    }
    RowLines(const RowLines&) = delete;  // st_ points into the object's own lists
    RowLines& operator=(const RowLines&) = delete;

    // Starts pixel row `row`, whose intervals, clipped to [x0, x1], go to `coverage` (local x from x0).
    void start(int row, double x0, double x1, RowCoverage& coverage) {
        st_.row = row;
        st_.clip_lo = x0;
        st_.clip_hi = x1;
        coverage_ = &coverage;
        for (LineUnion& line : lines_) line.clear();
        std::fill(open_lo_.begin(), open_lo_.end(), INFINITY);
        std::fill(open_hi_.begin(), open_hi_.end(), -INFINITY);
        std::fill(closed_hi_.begin(), closed_hi_.end(), -INFINITY);
        std::fill(settle_limit_.begin(), settle_limit_.end(), INFINITY);
    }

    // Adds the sections of caps[0 .. count) (their left ends in x0) to the row's lines; the
    // capsules come in order of their left ends.
    void add(const raster::SweptCapsule* const* caps, const double* x0, int count) {
        for (int c = 0; c < count;) {
            int s0 = 0, lines = 0;
            st_.n_runs = 0;
            c += raster::capsule_sections(caps + c, x0 + c, count - c, st_, &s0, &lines);
            for (int k = 0; k < st_.n_runs; ++k)
                coverage_->add_run(runs_[static_cast<std::size_t>(k)], static_cast<int>(st_.clip_lo));
            if (c == count) return;
            hand_over(x0[c], s0, lines);
            ++c;
        }
    }

    // Adds what is left of every line's union to the row's coverage.
    void accumulate() {
        for (std::size_t u = 0; u < lines_.size(); ++u)
            for (auto [l, h] : lines_[u].merged(open_lo_[u], open_hi_[u])) settle(l, h);
    }

private:
    // Takes what capsule_sections left of the capsule with left end x0 on its lines s0 .. s0 + n - 1:
    // the intervals it closed and did not settle, and the sections it could not fold.
    void hand_over(double x0, int s0, int n) {
        const double settled_below = raster::settle_bound(x0, kRoundingMargin);
        // Each line has at most one of the two bits.
        for (int word = 0; word <= (n - 1) / 64; ++word) {
            for (std::uint64_t bits = closed_bits_[word]; bits != 0; bits &= bits - 1) {
                const std::size_t t = static_cast<std::size_t>(word * 64 + std::countr_zero(bits));
                lines_[t + static_cast<std::size_t>(s0)].close(lo_[t], hi_[t], settled_below,
                                                               [this](double l, double h) { settle(l, h); });
            }
            for (std::uint64_t bits = left_bits_[word]; bits != 0; bits &= bits - 1) {
                const std::size_t t = static_cast<std::size_t>(word * 64 + std::countr_zero(bits));
                const std::size_t u = t + static_cast<std::size_t>(s0);
                lines_[u].add(lo_[t], hi_[t], open_lo_[u], open_hi_[u], closed_hi_[u]);
                if (!lines_[u].in_order()) settle_limit_[u] = -INFINITY;
            }
        }
    }

    // Adds the final interval [lo, hi] of one line, clipped, to the row's coverage.
    void settle(double lo, double hi) {
        lo = std::max(lo, st_.clip_lo);
        hi = std::min(hi, st_.clip_hi);
        if (hi > lo) coverage_->add(lo - st_.clip_lo, hi - st_.clip_lo);
    }

    // Far above the relative rounding of a section's ends (a few units of the last place): a
    // section may start left of its capsule's left end by that much.
    static constexpr double kRoundingMargin = std::is_same_v<Real, float> ? 1e-5 : 1e-9;
    static constexpr int kMaxRuns = 64;  // settled runs per call of capsule_sections
    RowCoverage* coverage_ = nullptr;
    std::vector<LineUnion> lines_;
    std::vector<Real> lo_, hi_;                        // one capsule's sections, from its first line
    std::vector<Real> open_lo_, open_hi_, closed_hi_;  // per line (LineUnion)
    std::vector<Real> settle_limit_;                   // per line: +infinity while in order
    std::vector<raster::SettledRun> runs_;
    std::uint64_t left_bits_[raster::kMaxSectionLines / 64], closed_bits_[raster::kMaxSectionLines / 64];
    raster::SectionRow<Real> st_;
};

// Throws for arguments round_stroke_spans() does not take (see casteljau/round_stroke.hpp).
void check_round_stroke(double radius, const IRect& clip, int lines_per_pixel) {
    if (!(radius > 0) || !std::isfinite(radius))
        throw Error(ErrorKind::InvalidArgument, "round_stroke_mask: the radius must be finite and > 0");
    if (lines_per_pixel < 1 || lines_per_pixel > kMaxRoundStrokeLines)
        throw Error(ErrorKind::InvalidArgument,
                    "round_stroke_mask: lines_per_pixel must be in [1, " + std::to_string(kMaxRoundStrokeLines) + "]");
    if (!clip.empty() && (clip.width() > limits::kMaxCanvasDimension || clip.height() > limits::kMaxCanvasDimension))
        throw Error(ErrorKind::Limit, "round_stroke_mask: the clip exceeds " +
                                          std::to_string(limits::kMaxCanvasDimension) + " pixels per side");
}

// Copies rows into a mask whose bytes start at 0.
class MaskRows final : public SpanSink {
public:
    explicit MaskRows(Mask& mask) : mask_(mask) {}
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        const IRect& b = mask_.bounds;
        std::copy(coverage, coverage + length,
                  mask_.data.begin() + static_cast<std::ptrdiff_t>(y - b.y0) * b.width() + (x - b.x0));
    }

private:
    Mask& mask_;
};

// The sweep of round_stroke_spans over the segments reaching the clip (caps), its sample lines in
// Real (float: segments cut by in_float_strip).
template <class Real>
void sweep(std::span<const LineSegment> segments, const std::vector<Extent>& caps, double radius, const IRect& clip,
           SpanSink& sink, int lines_per_pixel) {
    const int w = clip.width();
    RowCoverage row(w);
    RowLines<Real> lines(lines_per_pixel, radius);
    // The active capsules, each built once when its first row comes and kept in a slot of `built`
    // until its last row has gone.
    struct Active {
        std::uint32_t cap, slot;
    };
    std::vector<Active> active, merged;
    std::vector<SweptCapsule> built;
    std::vector<std::uint32_t> free_slots;
    std::vector<const SweptCapsule*> row_caps;  // the active capsules of a row, in order
    std::vector<double> row_x0;                 // and their left ends
    std::size_t next = 0;
    for (int j = clip.y0; j < clip.y1; ++j) {
        std::erase_if(active, [&](const Active& a) {
            if (caps[a.cap].y1 > j) return false;
            free_slots.push_back(a.slot);
            return true;
        });
        // The active list stays in order of the capsules' left ends, so that each line's intervals
        // arrive nearly sorted.
        const std::size_t kept = active.size();
        for (; next < caps.size() && caps[next].y0 < j + 1; ++next) {
            std::uint32_t slot;
            if (free_slots.empty()) {
                slot = static_cast<std::uint32_t>(built.size());
                built.emplace_back();
            } else {
                slot = free_slots.back();
                free_slots.pop_back();
            }
            // The segments come in order of their first rows, scattered in memory: fetch ahead.
            if (next + kFetchAhead < caps.size()) __builtin_prefetch(&segments[caps[next + kFetchAhead].segment]);
            const std::uint32_t i = caps[next].segment;
            const LineSegment& s = segments[i];
            built[slot] = make_capsule(std::is_same_v<Real, float> ? in_float_strip(s) : s, radius);
            // A polyline's segments come one after another: the previous one, a capsule of this
            // sweep too, already holds the disc where this one starts (or both were cut there,
            // where the disc cannot reach the clip).
            built[slot].start_disc = !(i > 0 && segments[i - 1].b == segments[i].a && built[slot].band);
            active.push_back({static_cast<std::uint32_t>(next), slot});
        }
        if (active.size() > kept && kept > 0) {  // the new ones came in order of their left ends
            merged.clear();
            auto left = [&](const Active& a, const Active& b) { return caps[a.cap].x0 < caps[b.cap].x0; };
            std::merge(active.begin(), active.begin() + static_cast<std::ptrdiff_t>(kept),
                       active.begin() + static_cast<std::ptrdiff_t>(kept), active.end(), std::back_inserter(merged),
                       left);
            active.swap(merged);
        }
        if (active.empty()) {
            if (next == caps.size()) break;
            continue;
        }
        lines.start(j, clip.x0, clip.x1, row);
        row_caps.clear();
        row_x0.clear();
        for (const Active& a : active) {
            row_caps.push_back(&built[a.slot]);
            row_x0.push_back(caps[a.cap].x0);
        }
        lines.add(row_caps.data(), row_x0.data(), static_cast<int>(row_caps.size()));
        lines.accumulate();
        row.emit(1.0 / lines_per_pixel, j, clip.x0, w, sink);
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
    mask.bounds = {};
    mask.data.clear();
    check_round_stroke(radius, clip, lines_per_pixel);
    if (clip.empty()) return;
    mask.bounds = clip;
    mask.data.assign(static_cast<std::size_t>(clip.width()) * static_cast<std::size_t>(clip.height()), 0);
    MaskRows rows(mask);
    round_stroke_spans(segments, radius, clip, rows, lines_per_pixel);
}

void round_stroke_spans(std::span<const LineSegment> segments, double radius, const IRect& clip, SpanSink& sink,
                        int lines_per_pixel) {
    check_round_stroke(radius, clip, lines_per_pixel);
    if (clip.empty()) return;
    const std::vector<Extent> caps = extents_in(segments, radius, clip);
    if (caps.empty()) return;
    // The choice depends on the clip's x only: the bands of an image, which differ in y, sweep alike.
    const double margin = radius + 1;
    if (clip.x0 - margin >= -kFloatSweepSide && clip.x1 + margin <= kFloatSweepSide)
        sweep<float>(segments, caps, radius, clip, sink, lines_per_pixel);
    else
        sweep<double>(segments, caps, radius, clip, sink, lines_per_pixel);
}

}  // namespace casteljau
