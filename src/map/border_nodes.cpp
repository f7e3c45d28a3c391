// Map stage: finding the nodes of the data's borders (src/map/border_nodes.hpp).
//
// One hash table of the distinct positions, each entry with the first pair of neighbours it was
// seen with; a later occurrence with another pair makes it a node. Neighbours are entry indices,
// so a pair compares as two integers.
#include "map/border_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "casteljau/error.hpp"
#include "map/point_hash.hpp"

namespace casteljau::map_detail {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// Open addressing with linear probing, the entries in the slots themselves (one cache miss per
// lookup, which the callers prefetch ahead of time). Slot index = entry id, so a table that grows
// gives its entries new ids (make_room).
class PositionTable {
public:
    // Room for `positions` entries.
    explicit PositionTable(std::size_t positions) : slots_(slots_for(positions)) {}

    // Makes room for `more` new entries. When the table has to grow, its entries move: the result
    // maps every old id to its new one (callers renumber the ids they hold); otherwise it is empty.
    std::vector<std::uint32_t> make_room(std::size_t more) {
        if (4 * (used_ + more) <= 3 * slots_.size()) return {};
        std::vector<Slot> old(slots_for(2 * (used_ + more)));
        old.swap(slots_);
        std::vector<std::uint32_t> moved(old.size(), kNone);
        for (std::size_t s = 0; s < old.size(); ++s)
            if (old[s].used) moved[s] = place(hash_point(old[s].p));
        for (std::size_t s = 0; s < old.size(); ++s) {
            if (!old[s].used) continue;
            Slot& x = slots_[moved[s]];
            x = old[s];
            if (x.a != kNone) x.a = moved[x.a];
            if (x.b != kNone) x.b = moved[x.b];
        }
        return moved;
    }

    std::size_t home(std::uint64_t hash) const {
        return static_cast<std::size_t>(((hash >> 32) * slots_.size()) >> 32);  // slots_.size() < 2^32
    }
    void prefetch(std::uint64_t hash) const { __builtin_prefetch(&slots_[home(hash)]); }
    void prefetch_entry(std::uint32_t e) const { __builtin_prefetch(&slots_[e]); }

    // The entry of position p (hash h), added when it is new (make_room first).
    std::uint32_t find_or_add(Point p, std::uint64_t h) {
        for (std::size_t s = home(h);; s = s + 1 == slots_.size() ? 0 : s + 1) {
            Slot& x = slots_[s];
            if (!x.used) {
                x = Slot{p, kNone, kNone, 1, 0};
                ++used_;
                return static_cast<std::uint32_t>(s);
            }
            if (x.p == p) return static_cast<std::uint32_t>(s);
        }
    }

    // Records that entry e occurs between entries u and v.
    void neighbours(std::uint32_t e, std::uint32_t u, std::uint32_t v) {
        Slot& x = slots_[e];
        if (u > v) std::swap(u, v);
        if (x.a == kNone) {
            x.a = u;
            x.b = v;
        } else if (x.a != u || x.b != v) {
            x.node = 1;
        }
    }

    void make_node(std::uint32_t e) { slots_[e].node = 1; }
    bool is_node(std::uint32_t e) const { return slots_[e].node != 0; }

private:
    struct Slot {
        Point p;
        std::uint32_t a = kNone, b = kNone;  // the first pair of neighbours, a <= b (kNone: not seen yet)
        std::uint8_t used = 0, node = 0;
    };

    static std::size_t slots_for(std::size_t entries) {
        const std::size_t n = entries + entries / 3 + 64;
        if (n >= kNone) throw Error(ErrorKind::Limit, "border nodes: too many positions");
        return n;
    }

    // The free slot a new position of hash h takes (one the table does not hold).
    std::uint32_t place(std::uint64_t h) {
        std::size_t s = home(h);
        while (slots_[s].used) s = s + 1 == slots_.size() ? 0 : s + 1;
        slots_[s].used = 1;
        return static_cast<std::uint32_t>(s);
    }

    std::vector<Slot> slots_;
    std::size_t used_ = 0;
};

constexpr std::size_t kAhead = 8;  // lookups prefetched ahead

// Adds one ring or line (positions `pts`, the first of which has index `base` in the result) to
// the table, and its entries to ids (kNone for the positions skipped).
void add_line(std::span<const Point> pts, bool closed, std::size_t base, PositionTable& table,
              std::vector<std::uint32_t>& ids, std::vector<std::uint32_t>& distinct, std::vector<std::uint64_t>& hashes,
              std::vector<std::uint32_t>& ring) {
    distinct_positions(pts, closed, distinct);
    const std::size_t m = distinct.size();
    hashes.resize(m);
    for (std::size_t k = 0; k < m; ++k) hashes[k] = hash_point(pts[distinct[k]]);
    ring.resize(m);
    for (std::size_t k = 0; k < m; ++k) {
        if (k + kAhead < m) table.prefetch(hashes[k + kAhead]);
        ring[k] = table.find_or_add(pts[distinct[k]], hashes[k]);
        ids[base + distinct[k]] = ring[k];
        // The previous position's neighbours are known now, and its entry is still in cache.
        if (m >= 3 && k >= 2) table.neighbours(ring[k - 1], ring[k - 2], ring[k]);
    }
    if (m < 3) {
        for (std::uint32_t e : ring) table.make_node(e);
        return;
    }
    if (closed) {
        table.neighbours(ring[m - 1], ring[m - 2], ring[0]);
        table.neighbours(ring[0], ring[m - 1], ring[1]);
    } else {
        table.make_node(ring[0]);
        table.make_node(ring[m - 1]);
    }
    for (std::size_t k = 0; k + 1 < m + (closed ? 1 : 0); ++k) {
        const std::size_t next = (k + 1) % m;
        if (std::fabs(pts[distinct[next]].x - pts[distinct[k]].x) > 180) {
            table.make_node(ring[k]);
            table.make_node(ring[next]);
        }
    }
}

}  // namespace

void distinct_positions(std::span<const Point> line, bool closed, std::vector<std::uint32_t>& out) {
    out.clear();
    for (std::size_t i = 0; i < line.size(); ++i)
        if (out.empty() || !(line[i] == line[out.back()])) out.push_back(static_cast<std::uint32_t>(i));
    if (closed)
        while (out.size() > 1 && line[out.back()] == line[out.front()]) out.pop_back();
}

namespace {

// Calls each(line, closed, first) for every ring (closed) and line of geometry g, whose first
// position has index base in BorderNodes::node; first is the index of the line's first position.
template <class Each>
void for_each_ring(const Geometry& g, std::size_t base, Each&& each) {
    if (g.kind == GeometryKind::Points) return;
    std::uint32_t start = 0;
    const std::span<const Point> pts(g.points);
    for (std::uint32_t end : g.ring_ends) {
        each(pts.subspan(start, end - start), g.kind == GeometryKind::Polygons, base + start);
        start = end;
    }
}

// The same for every ring and line of the data.
template <class Each>
void for_each_line(const MapData& data, Each&& each) {
    std::size_t base = 0;
    for (const Feature& f : data.features)
        for (const Geometry& g : f.geometries) {
            for_each_ring(g, base, each);
            base += g.points.size();
        }
}

// Any data: the table of every position and its neighbours.
void nodes_from_positions(const MapData& data, BorderNodes& r) {
    const std::size_t total = r.node.size();
    // The table grows with the distinct positions: data that repeats its positions (neighbours'
    // borders, repeated features) needs far fewer entries than it has positions.
    PositionTable table(std::min<std::size_t>(total, 1 << 16));
    std::vector<std::uint32_t> ids(total, kNone), distinct, ring;
    std::vector<std::uint64_t> hashes;
    for_each_line(data, [&](std::span<const Point> pts, bool closed, std::size_t base) {
        const std::vector<std::uint32_t> moved = table.make_room(pts.size());
        if (!moved.empty())
            for (std::size_t i = 0; i < base; ++i)
                if (ids[i] != kNone) ids[i] = moved[ids[i]];
        add_line(pts, closed, base, table, ids, distinct, hashes, ring);
    });
    for (std::size_t i = 0; i < total; ++i) {
        if (i + kAhead < total && ids[i + kAhead] != kNone) table.prefetch_entry(ids[i + kAhead]);
        if (ids[i] != kNone && table.is_node(ids[i])) r.node[i] = 1;
    }
}

// Marks in `node` (indexed like pts) the positions of one ring or line that are nodes whatever its
// neighbours: every position of one with fewer than three distinct positions, a line's ends, and
// the ends of a step across the antimeridian. `distinct` holds distinct_positions(pts, closed).
void intrinsic_nodes(std::span<const Point> pts, bool closed, std::span<const std::uint32_t> distinct,
                     std::span<std::uint8_t> node) {
    const std::size_t m = distinct.size();
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t next = k + 1 == m ? 0 : k + 1;
        if (m < 3 || (!closed && (k == 0 || k + 1 == m))) node[distinct[k]] = 1;
        if ((closed || k + 1 < m) && std::fabs(pts[distinct[next]].x - pts[distinct[k]].x) > 180)
            node[distinct[k]] = node[distinct[next]] = 1;
    }
}

// Marks in `node` (indexed like pts) the positions of one ring or line where it passes from one arc
// to the next: `starts`, its arc starts as indices into its geometry's positions, of which pts
// begins at `offset` (any before it are ignored). An arc start that repeats a position counts for
// the first of its repeats (the one distinct_positions keeps); one among a ring's closing repeats,
// for its first position.
void arc_start_nodes(std::span<const Point> pts, std::span<const std::uint32_t> distinct,
                     std::span<const std::uint32_t> starts, std::size_t offset, std::span<std::uint8_t> node) {
    if (distinct.empty()) return;
    std::size_t k = 0;  // the group of repeats the arc start falls in
    for (const std::uint32_t at : starts) {
        if (at < offset) continue;
        const std::size_t i = at - offset;
        while (k + 1 < distinct.size() && distinct[k + 1] <= i) ++k;
        node[pts[i] == pts[distinct[k]] ? distinct[k] : distinct[0]] = 1;
    }
}

// TopoJSON: every ring and line is a chain of arcs, and a border two rings share is one arc, so
// the nodes are where a ring or line passes from one arc to the next (Geometry::arc_starts), and
// what every ring or line has whatever its neighbours.
void nodes_from_arcs(const MapData& data, BorderNodes& r) {
    std::vector<std::uint32_t> distinct;
    std::size_t base = 0;
    for (const Feature& f : data.features)
        for (const Geometry& g : f.geometries) {
            const std::span<const std::uint32_t> starts(g.arc_starts);
            std::size_t next = 0;  // the first arc start not yet placed
            for_each_ring(g, base, [&](std::span<const Point> pts, bool closed, std::size_t first) {
                const std::span<std::uint8_t> node = std::span<std::uint8_t>(r.node).subspan(first, pts.size());
                const std::size_t start = first - base, from = next;
                while (next < starts.size() && starts[next] < start + pts.size()) ++next;
                distinct_positions(pts, closed, distinct);
                intrinsic_nodes(pts, closed, distinct, node);
                arc_start_nodes(pts, distinct, starts.subspan(from, next - from), start, node);
            });
            base += g.points.size();
        }
}

// Whether the data's rings and lines were assembled from arcs, each geometry with its arc starts.
bool has_arc_starts(const MapData& data) {
    if (data.arc_ends.empty()) return false;
    for (const Feature& f : data.features)
        for (const Geometry& g : f.geometries)
            if (g.kind != GeometryKind::Points && !g.points.empty() && g.arc_starts.empty()) return false;
    return true;
}

}  // namespace

BorderNodes find_border_nodes(const MapData& data) {
    BorderNodes r;
    r.feature_start.reserve(data.features.size() + 1);
    std::size_t total = 0;
    for (const Feature& f : data.features) {
        r.feature_start.push_back(total);
        for (const Geometry& g : f.geometries) total += g.points.size();
    }
    r.feature_start.push_back(total);
    r.node.assign(total, 0);
    if (has_arc_starts(data))
        nodes_from_arcs(data, r);
    else
        nodes_from_positions(data, r);
    return r;
}

}  // namespace casteljau::map_detail
