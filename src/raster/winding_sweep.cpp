// Raster stage: the winding sweep (see winding_sweep.hpp).
#include "raster/winding_sweep.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "casteljau/error.hpp"
#include "raster/engine.hpp"

namespace casteljau::raster {

namespace {

// Two neighbours whose order is wrong by at most this much (in pixels) are taken as touching, not
// crossing: the area this misplaces is below kTouch x the strip's height.
constexpr double kTouch = 1e-9;

// The order of chains at a strip's top: by x, and chains that meet there by their slope (the one
// further left just below comes first).
inline bool before(const auto& a, const auto& b) { return a.x < b.x - kTouch || (a.x <= b.x + kTouch && a.k < b.k); }

}  // namespace

void WindingSweep::begin(std::size_t max_edges, bool keep_outline) {
    keep_outline_ = keep_outline;
    outline_.clear();
    outline_ends_.clear();
    pts_.clear();
    chains_.clear();
    open_ = false;
    count_ = 0;
    max_edges_ = max_edges;
}

void WindingSweep::too_many() const {
    throw Error(ErrorKind::Limit, "path too complex: more than " + std::to_string(max_edges_) + " edges");
}

void WindingSweep::close_chain() {
    if (!open_) return;
    Chain& c = chains_.back();
    c.last = static_cast<std::uint32_t>(pts_.size() - 1);
    Pt* const first = pts_.data() + c.first;
    Pt* const end = pts_.data() + pts_.size();
    if (c.dir < 0) std::reverse(first, end);
    // The x range in a pass of its own: kept while the points arrive, it costs more (the
    // compiler packs it into vectors along with the points).
    double xmin = first->x, xmax = first->x;
    for (const Pt* q = first + 1; q < end; ++q) {
        // One minsd and one maxsd each (std::min's argument order costs a move per point).
        xmin = q->x < xmin ? q->x : xmin;
        xmax = q->x > xmax ? q->x : xmax;
    }
    c.xmin = xmin;
    c.xmax = xmax;
    open_ = false;
}

void WindingSweep::start_chain(double x0, double y0, std::int8_t dir) {
    close_chain();
    chains_.push_back({static_cast<std::uint32_t>(pts_.size()), 0, dir, 0, 0});
    pts_.push({x0, y0});
    open_ = true;
}

void WindingSweep::push_whole(const Chain& c, int sign, Engine& out) const {
    static_assert(sizeof(Pt) == 2 * sizeof(double));
    out.push_chain(&pts_[c.first].x, c.last - c.first + 1, c.dir * sign < 0);
}

void WindingSweep::push_outline(Engine& out) const {
    std::size_t start = 0;
    for (const std::uint32_t end : outline_ends_) {
        out.push_polyline(outline_.data() + 2 * start, end - start);
        start = end;
    }
}

void WindingSweep::push_polyline(const double* xy, std::size_t n) {
    if (keep_outline_) {
        outline_.insert(outline_.end(), xy, xy + 2 * n);
        outline_ends_.push_back(static_cast<std::uint32_t>(outline_.size() / 2));
    }
    if (n < 2) return;
    // The direction of the open chain when these edges continue it, else 0.
    std::int8_t dir = open_ && continues(xy[0], xy[1]) ? chains_.back().dir : 0;
    // Each edge adds its end, and at most one chain start: room for 2 n points. The points are
    // written through p, which is committed before a chain starts and at the end.
    Pt* p = pts_.room(2 * n);
    std::size_t zero = 0;  // point-like edges, which are dropped
    // Only the start's y is carried from edge to edge; the rare paths read its x back.
    double y0 = xy[1];
    for (const double *e = xy + 2, *const stop = xy + 2 * n; e != stop; e += 2) {
        const double y1 = e[1];
        if (y1 == y0) [[unlikely]] {
            if (e[0] == e[-2])
                ++zero;
            else
                dir = 0;  // bounds no strip; the next edge starts a chain
            continue;
        }
        const std::int8_t d = y1 > y0 ? 1 : -1;
        if (d != dir) [[unlikely]] {
            pts_.commit(p);
            start_chain(e[-2], y0, d);
            p = pts_.data() + pts_.size();
            dir = d;
        }
        std::memcpy(p++, e, sizeof(Pt));  // the point as it is: x and y, as Pt lays them out
        y0 = y1;
    }
    pts_.commit(p);
    // The limit is checked once per polyline, which lets at most its points past it.
    count_ += n - 1 - zero;
    if (count_ > max_edges_) too_many();
}

void WindingSweep::trim(std::size_t points) {
    if (pts_.capacity() <= points) return;
    std::vector<double>().swap(outline_);
    std::vector<std::uint32_t>().swap(outline_ends_);
    pts_.release_above(0);
    std::vector<Chain>().swap(chains_);
    std::vector<std::pair<double, std::uint32_t>>().swap(order_);
    std::vector<Active>().swap(active_);
    std::vector<Probe>().swap(probes_);
    open_ = false;
}

void WindingSweep::flush(const Active& a, double y, Engine& out) const {
    if (a.keep == 0 || !(y > a.ys)) return;
    double px = x_on(a.seg_s, a.ys), py = a.ys;
    auto emit = [&](double x, double yy) {
        if (a.keep > 0)
            out.push(px, py, x, yy);
        else
            out.push(x, yy, px, py);
        px = x;
        py = yy;
    };
    std::uint32_t j = a.seg_s + 1;
    for (; j <= a.last && pts_[j].y < y; ++j) emit(pts_[j].x, pts_[j].y);
    emit(x_on(j - 1, y), y);
}

double WindingSweep::first_crossing(const Active& a, const Active& b, double y, double end, std::size_t& work) const {
    if (a.xmax <= b.xmin) return end;  // a lies left of b all along
    std::uint32_t ia = a.seg, ib = b.seg;
    double prev = y, fprev = a.x - b.x;
    while (prev < end) {
        const double v = std::min({pts_[ia + 1].y, pts_[ib + 1].y, end});
        const double f = x_on(ia, v) - x_on(ib, v);
        if (f > kTouch) return prev + (v - prev) * (std::max(0.0, -fprev) / (f - fprev));
        ++work;
        if (pts_[ia + 1].y <= v && ia + 1 < a.last) ++ia;
        if (pts_[ib + 1].y <= v && ib + 1 < b.last) ++ib;
        prev = v;
        fprev = f;
    }
    return end;
}

bool WindingSweep::probes_cross(Probe& a, Probe& b, double y, std::size_t& work) const {
    const Chain& ca = chains_[a.chain];
    const Chain& cb = chains_[b.chain];
    if (ca.xmax <= cb.xmin + kTouch) return false;  // a lies left of b all along
    // x_a - x_b is linear between the points of either chain, and at most kTouch at y: the two
    // cross if and only if it exceeds kTouch at one of those points. Each point is tested against
    // the other chain's segment at its height by a cross product, with no division.
    const double end = std::min(a.bottom, b.bottom);
    // From the segments at y (kept in the probes: the next check of either starts there).
    std::uint32_t ia = segment_at(a, y), ib = segment_at(b, y);
    while (true) {
        ++work;
        const Pt& a0 = pts_[ia];
        const Pt& a1 = pts_[ia + 1];
        const Pt& b0 = pts_[ib];
        const Pt& b1 = pts_[ib + 1];
        if (a1.y <= b1.y) {
            if (side(a1, b0, b1) > kTouch * (b1.y - b0.y)) return true;  // a's point right of b
            if (a1.y >= end) return false;
            if (a1.y == b1.y) ++ib;
            ++ia;
        } else {
            if (-side(b1, a0, a1) > kTouch * (a1.y - a0.y)) return true;  // b's point left of a
            if (b1.y >= end) return false;
            ++ib;
        }
    }
}

bool WindingSweep::insert_probe(std::uint32_t c, double y) {
    const Chain& ch = chains_[c];
    const Pt p = pts_[ch.first], q = pts_[ch.first + 1];
    std::size_t at = 0;
    for (; at < probes_.size(); ++at) {
        // Most chains lie wholly on one side of p: their x range tells, without their segments.
        const Chain& other = chains_[probes_[at].chain];
        if (p.x > other.xmax + kTouch) continue;
        if (p.x < other.xmin - kTouch) break;
        const Pt& a0 = pts_[segment_at(probes_[at], y)];
        const Pt& a1 = pts_[probes_[at].seg + 1];
        const double dy = a1.y - a0.y, at_side = side(p, a0, a1);
        if (at_side < -kTouch * dy) break;
        if (at_side > kTouch * dy) continue;
        // p touches it: the one further left just below comes first.
        const double turn = (q.x - p.x) * dy - (a1.x - a0.x) * (q.y - p.y);
        if (turn < 0) break;
        if (!(turn > 0)) return false;
    }
    probes_.insert(probes_.begin() + static_cast<std::ptrdiff_t>(at),
                   Probe{pts_[ch.last].y, c, ch.first, std::numeric_limits<std::uint32_t>::max(), ch.dir});
    return true;
}

bool WindingSweep::prove_one_value(std::size_t budget) {
    probes_.clear();
    std::size_t next_top = 0, work = 0;
    s_ = 0;
    double y = order_[0].first;
    while (true) {
        proven_to_ = y;
        // The chains ending at y leave, those starting there enter.
        std::erase_if(probes_, [y](const Probe& p) { return p.bottom <= y; });
        for (; next_top < order_.size() && order_[next_top].first <= y; ++next_top) {
            work += probes_.size();  // the insertion's search
            if (work > budget || !insert_probe(order_[next_top].second, y)) return false;
        }
        if (s_ == 0 && !probes_.empty()) s_ = probes_[0].dir;
        // Below y, up to the next top or bottom: the directions alternate from s, and no two
        // neighbours cross (each pair checked once over the height both span).
        double next = next_top < order_.size() ? order_[next_top].first : std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < probes_.size(); ++i) {
            Probe& p = probes_[i];
            if (p.dir != ((i & 1) ? -s_ : s_)) return false;
            next = std::min(next, p.bottom);
            if (i + 1 == probes_.size() || p.right == probes_[i + 1].chain) continue;
            if (probes_cross(p, probes_[i + 1], y, work)) return false;
            p.right = probes_[i + 1].chain;
        }
        work += probes_.size();
        if (work > budget) return false;
        if (next == std::numeric_limits<double>::infinity()) return true;
        y = next;
    }
}

void WindingSweep::resume_strips() {
    const double y = proven_to_;
    active_.clear();
    for (next_top_ = 0; next_top_ < order_.size() && order_[next_top_].first < y; ++next_top_) {
        const Chain& c = chains_[order_[next_top_].second];
        if (pts_[c.last].y <= y) continue;  // ended above y: take_over() pushes it whole if needed
        const std::uint32_t seg = segment_below(c.first, y);
        // Kept (once kept) from its top, as enter() would have made it there.
        active_.push_back({x_on(seg, y), slope(seg), pts_[c.last].y, order_[next_top_].first, seg, c.first, c.last,
                           c.xmin, c.xmax, c.dir, 0});
    }
}

[[gnu::always_inline]] inline void WindingSweep::enter(double y) {
    for (; next_top_ < order_.size() && order_[next_top_].first <= y; ++next_top_) {
        const Chain& c = chains_[order_[next_top_].second];
        active_.push_back(
            {pts_[c.first].x, slope(c.first), pts_[c.last].y, y, c.first, c.first, c.last, c.xmin, c.xmax, c.dir, 0});
    }
}

[[gnu::always_inline]] inline double WindingSweep::strip_end(double y, double next, std::size_t& work) {
    // Insertion sort: the order of the strip before is nearly this one.
    for (std::size_t i = 1; i < active_.size(); ++i) {
        if (!before(active_[i], active_[i - 1])) continue;
        const Active a = active_[i];
        std::size_t j = i;
        for (; j > 0 && before(a, active_[j - 1]); --j) active_[j] = active_[j - 1];
        active_[j] = a;
    }
    for (const Active& a : active_) next = std::min(next, a.bottom);
    for (std::size_t i = 0; i + 1 < active_.size(); ++i)
        next = first_crossing(active_[i], active_[i + 1], y, next, work);
    work += active_.size();
    return next;
}

[[gnu::always_inline]] inline void WindingSweep::choose(FillRule rule, double y, Engine& out) {
    // Left to right with the running winding number: a chain bounds the filled region where the
    // number changes between zero and nonzero (nonzero rule), or always (even-odd). Kept chains
    // run down where the region starts and up where it ends, so every run of it winds +1.
    int w = 0;
    std::int8_t side = 1;
    for (Active& a : active_) {
        std::int8_t keep;
        if (rule == FillRule::NonZero) {
            const int was = w;
            w += a.dir;
            keep = was == 0 ? 1 : (w == 0 ? -1 : 0);
        } else {
            keep = side;
            side = static_cast<std::int8_t>(-side);
        }
        if (keep == a.keep) continue;
        flush(a, y, out);
        a.keep = keep;
        a.ys = y;
        a.seg_s = a.seg;
    }
}

template <bool kEmit>
[[gnu::always_inline]] inline void WindingSweep::advance(double y, Engine& out) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < active_.size(); ++i) {
        const Active& a = active_[i];
        if (a.bottom <= y) {
            if constexpr (kEmit) flush(a, a.bottom, out);
            continue;
        }
        const std::uint32_t s = segment_below(a.seg, y);
        // Copy first, then set x: writing x before copying the whole record stalls the copy.
        if (kept != i) active_[kept] = a;
        Active& k = active_[kept++];
        k.seg = s;
        k.x = x_on(s, y);
        k.k = slope(s);
    }
    active_.resize(kept);
}

[[gnu::always_inline]] inline bool WindingSweep::one_value() {
    int w = 0;
    for (const Active& a : active_) {
        w += a.dir;
        if (w == 0) continue;
        if (s_ == 0) s_ = w;
        if (w != s_) return false;
    }
    return true;
}

void WindingSweep::take_over(double y, Engine& out) {
    if (!keep_outline_) out.restart();  // it holds the pushed edges: the boundary replaces them
    // Above y every strip wound 0 and s_ only, where each chain bounds the region: run down where
    // the region starts, so a chain is kept in its own direction times s_ and the region winds +1,
    // as choose() keeps it from here on.
    for (std::size_t i = 0; i < next_top_; ++i) {
        const Chain& c = chains_[order_[i].second];
        if (pts_[c.last].y <= y) push_whole(c, s_, out);
    }
    // The chains still active have kept their pieces from their tops (ys, seg_s) on.
    for (Active& a : active_) a.keep = static_cast<std::int8_t>(a.dir * s_);
}

WindingSweep::Outcome WindingSweep::fill(FillRule rule, std::size_t budget, Engine& out) {
    close_chain();
    if (chains_.empty()) return Outcome::Simple;
    order_.clear();
    for (std::uint32_t c = 0; c < chains_.size(); ++c) order_.emplace_back(pts_[chains_[c].first].y, c);
    std::sort(order_.begin(), order_.end());
    if (prove_one_value(budget)) {
        if (keep_outline_) push_outline(out);
        return Outcome::Simple;
    }
    // The strips go on from where the proof stopped, with its s_.
    resume_strips();
    bool proving = true;  // every strip so far wound 0 and s_ only
    std::size_t work = 0;
    double y = proven_to_;
    while (true) {
        enter(y);
        if (active_.empty()) {
            if (next_top_ == order_.size()) break;
            y = order_[next_top_].first;
            continue;
        }
        const double top =
            next_top_ < order_.size() ? order_[next_top_].first : std::numeric_limits<double>::infinity();
        const double next = strip_end(y, top, work);
        if (work > budget || !(next > y)) return Outcome::TooCostly;
        if (proving && !one_value()) {
            proving = false;
            take_over(y, out);
        }
        if (proving) {
            advance<false>(next, out);
        } else {
            choose(rule, y, out);
            advance<true>(next, out);
        }
        y = next;
    }
    if (!proving) return Outcome::Swept;
    if (keep_outline_) push_outline(out);
    return Outcome::Simple;
}

}  // namespace casteljau::raster
