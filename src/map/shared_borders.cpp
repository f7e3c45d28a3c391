// Map stage: SharedBorders (casteljau/map.hpp), the rings of neighbouring polygons with what an
// earlier ring already holds taken out, so that each border is stroked once.
//
// Every ring added is kept in pts_ as its n positions followed by its first two again, so segment i
// of a ring starting at `base` is (pts_[base + i], pts_[base + i + 1]) for i < n and vertex j is
// pts_[base + j] between pts_[base + j - 1] and pts_[base + j + 1] for 1 <= j <= n (j = n is the
// first position). The two hash tables hold the index of a segment's first position or of a join's
// vertex (plus one), compared by the positions themselves, so the answers are exact.
#include <cstring>

#include "casteljau/error.hpp"
#include "casteljau/map.hpp"
#include "casteljau/stroke.hpp"
#include "map/point_hash.hpp"

namespace casteljau {

namespace {

using map_detail::hash_point;
using map_detail::mix;

constexpr std::size_t kMaxPositions = std::size_t(1) << 31;

bool same(Point a, Point b) { return a.x == b.x && a.y == b.y; }

}  // namespace

void SharedBorders::clear() {
    pts_.clear();
    std::fill(segments_.begin(), segments_.end(), 0u);
    std::fill(joins_.begin(), joins_.end(), 0u);
    segment_count_ = join_count_ = 0;
}

// The slot of the segment starting at pts_[a] (either direction): the one holding it, or the empty
// one where it goes.
std::uint32_t* SharedBorders::find_segment(std::uint32_t a) {
    const Point p = pts_[a], q = pts_[a + 1];
    const std::size_t mask = segments_.size() - 1;
    for (std::size_t s = mix(hash_point(p) + hash_point(q)) & mask;; s = (s + 1) & mask) {
        const std::uint32_t e = segments_[s];
        if (e == 0) return &segments_[s];
        const Point u = pts_[e - 1], v = pts_[e];
        if ((same(u, p) && same(v, q)) || (same(u, q) && same(v, p))) return &segments_[s];
    }
}

// The slot of the join at pts_[v] (its neighbours in either order).
std::uint32_t* SharedBorders::find_join(std::uint32_t v) {
    const Point a = pts_[v - 1], p = pts_[v], b = pts_[v + 1];
    const std::size_t mask = joins_.size() - 1;
    for (std::size_t s = mix(3 * hash_point(p) + hash_point(a) + hash_point(b)) & mask;; s = (s + 1) & mask) {
        const std::uint32_t e = joins_[s];
        if (e == 0) return &joins_[s];
        const Point u = pts_[e - 2], w = pts_[e - 1], x = pts_[e];
        if (same(w, p) && ((same(u, a) && same(x, b)) || (same(u, b) && same(x, a)))) return &joins_[s];
    }
}

// Doubles a table (or gives it its first 1024 slots) and inserts its entries again.
void SharedBorders::grow(std::vector<std::uint32_t>& table, bool joins) {
    std::vector<std::uint32_t> old = std::move(table);
    table.assign(old.empty() ? 1024 : old.size() * 2, 0u);
    for (std::uint32_t e : old)
        if (e != 0) *(joins ? find_join(e - 1) : find_segment(e - 1)) = e;
}

bool SharedBorders::add_ring(std::span<const Point> ring, Path& out, double merge_distance) {
    // The stroker takes a position within merge_distance of the last one it kept (and, closing,
    // of the first) as that one, so its segments and joins are those of the ring so merged: merge
    // it the same way, with its own test, before comparing borders. A repeat carries no segment.
    ring_.clear();
    auto apart = [merge_distance](Point a, Point b) { return stroke_keeps_apart(a, b, merge_distance); };
    for (Point p : ring)
        if (ring_.empty() || apart(p, ring_.back())) ring_.push_back(p);
    while (ring_.size() > 1 && !apart(ring_.back(), ring_.front())) ring_.pop_back();
    const std::size_t n = ring_.size();
    if (n < 3) return false;  // a point or a there-and-back: its stroke depends on the caps
    // Of zero length for the stroker (casteljau/stroke.hpp): a dot, which depends on the caps too.
    bool spread = false;
    for (Point p : ring_) spread = spread || distance(p, ring_[0]) > merge_distance;
    if (!spread) return false;
    const std::size_t base = pts_.size();
    if (base + n + 2 > kMaxPositions)
        throw Error(ErrorKind::Limit, "shared borders: more than 2^31 positions between clear() calls");
    pts_.insert(pts_.end(), ring_.begin(), ring_.end());
    pts_.push_back(ring_[0]);
    pts_.push_back(ring_[1]);
    // flags_[i]: bit 0 segment i was held already, bit 1 the join at vertex i (i = 0: the first
    // position, stored as vertex n) is new.
    flags_.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if ((segment_count_ + 1) * 2 > segments_.size()) grow(segments_, false);
        std::uint32_t* slot = find_segment(static_cast<std::uint32_t>(base + i));
        if (*slot != 0) {
            flags_[i] |= 1;
        } else {
            *slot = static_cast<std::uint32_t>(base + i + 1);
            ++segment_count_;
        }
    }
    for (std::size_t j = 1; j <= n; ++j) {
        if ((join_count_ + 1) * 2 > joins_.size()) grow(joins_, true);
        std::uint32_t* slot = find_join(static_cast<std::uint32_t>(base + j));
        if (*slot == 0) {
            *slot = static_cast<std::uint32_t>(base + j + 1);
            ++join_count_;
            flags_[j % n] |= 2;
        }
    }
    // Segment i is drawn when it is new or when a new join sits at either of its ends.
    auto drawn = [&](std::size_t i) { return !(flags_[i] & 1) || (flags_[i] & 2) || (flags_[(i + 1) % n] & 2); };
    std::size_t skip = n;
    for (std::size_t i = 0; i < n && skip == n; ++i)
        if (!drawn(i)) skip = i;
    if (skip == n) {
        out.add_polygon(ring_, true);
        return true;
    }
    bool open = false;
    for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t i = (skip + k) % n;
        if (!drawn(i)) {
            open = false;
            continue;
        }
        if (!open) out.move_to(ring_[i]);
        out.line_to(ring_[(i + 1) % n]);
        open = true;
    }
    return true;
}

void SharedBorders::add(const Path& rings, Path& chains, Path& whole, double merge_distance) {
    const auto verbs = rings.verbs();
    const auto pts = rings.points();
    const auto weights = rings.weights();
    std::size_t v = 0, p = 0, w = 0;
    while (v < verbs.size()) {
        // One contour: verbs [v, ve), points [p, pe), weights [w, we).
        std::size_t ve = v, pe = p, we = w;
        bool lines_only = true, closed = false;
        do {
            const Verb verb = verbs[ve];
            lines_only = lines_only && (verb == Verb::Move || verb == Verb::Line || verb == Verb::Close);
            closed = closed || verb == Verb::Close;
            pe += static_cast<std::size_t>(verb_point_count(verb));
            if (verb == Verb::Conic) ++we;
            ++ve;
        } while (ve < verbs.size() && verbs[ve] != Verb::Move);
        if (!(lines_only && closed && add_ring(pts.subspan(p, pe - p), chains, merge_distance))) {
            std::size_t pi = p, wi = w;
            for (std::size_t i = v; i < ve; ++i) {
                switch (verbs[i]) {
                    case Verb::Move: whole.move_to(pts[pi]); break;
                    case Verb::Line: whole.line_to(pts[pi]); break;
                    case Verb::Quad: whole.quad_to(pts[pi], pts[pi + 1]); break;
                    case Verb::Cubic: whole.cubic_to(pts[pi], pts[pi + 1], pts[pi + 2]); break;
                    case Verb::Conic: whole.conic_to(pts[pi], pts[pi + 1], weights[wi++]); break;
                    case Verb::Close: whole.close(); break;
                }
                pi += static_cast<std::size_t>(verb_point_count(verbs[i]));
            }
        }
        v = ve;
        p = pe;
        w = we;
    }
}

}  // namespace casteljau
