// Internal: the raster stage's winding sweep. It turns the edges of any closed shape (contours
// that overlap, cross themselves or each other, under either fill rule) into the edges of the
// region it fills, each oriented so that the winding number they make is 1 inside that region and
// 0 outside. Plain cover/area accumulation of the result is then the exact coverage of the shape,
// with no overlap check per cell.
//
// How: the edges are joined into chains (runs of a contour going the same way, up or down). A
// sweep down the shape keeps the chains that span the current horizontal strip sorted by x. A
// strip ends at the next chain's top or bottom or at the first crossing of two neighbours, so the
// order holds inside it, and the winding number between two neighbours is constant there.
// Walking the strip's chains left to right with the running winding number says which of them
// bound the filled region: those where it changes between zero and nonzero (nonzero rule), or
// every one (even-odd). The others (inside an overlap) are dropped; a bounding chain is kept for
// as many strips as it stays bounding. Horizontal edges bound no strip and are dropped.
//
// Most shapes (glyphs, icons) wind 0 and one other value only; every chain bounds their region,
// and their own edges are already exact. Such a shape is proven first, without strips: it winds
// one value if no two chains cross and the chains' directions alternate from left to right (the
// first one's direction, s, then -s, s, ...) after every chain top and bottom. As in a
// Bentley-Ottmann sweep, the first crossing below any y is between chains that are neighbours at
// y, so each pair of chains that becomes neighbours is checked once, over the height both span,
// and nothing is done between the tops and bottoms. A shape that passes goes on with its edges
// whole, as they came (the polylines are kept beside the chains, or the caller gave them to the
// engine as well): the engine then gets what it would have got without the sweep, in outline
// order. Any other, or one the proof cannot order (two chains starting along one line), goes to
// the strips from the y where the proof stopped (everything above it is proven): they check each
// strip for one value, cut nothing while it holds, and cut the shape into its region's boundary
// from the first strip that fails.
//
// Cost: the edges, plus the strips times the chains spanning them. A shape with many crossings
// (each one a strip) may cost more than the per-cell check, so the sweep stops at a budget and
// says so.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "casteljau/raster.hpp"
#include "raster/raster_internal.hpp"

namespace casteljau::raster {

class Engine;

class WindingSweep {
public:
    // Starts a shape; more than `max_edges` edges pushed is a Limit error. `keep_outline`: keep the
    // pushed edges to hand them to fill()'s engine if the shape is simple; without it the caller
    // pushes every edge into that engine too, as it pushes them here (see fill()).
    void begin(std::size_t max_edges, bool keep_outline = true);
    // One edge in box coordinates, in contour order (the edge builder's interface).
    inline void push(double x0, double y0, double x1, double y1);
    // The edges between n consecutive points (x and y interleaved), as push() for each.
    void push_polyline(const double* xy, std::size_t n);
    void contour_end() {}
    std::size_t edges() const { return count_; }
    // Frees the buffers that hold room for more than `points` points (between shapes).
    void trim(std::size_t points);
    // Pushes into `out`, an engine begun without the overlap check on the same box, edges whose
    // plain accumulation renders the region the pushed edges fill under `rule` exactly:
    // - Simple: the shape winds 0 and one other value only (as glyphs do), under either rule
    //   exact as it is; its own edges are pushed whole once the sweep has proven it.
    // - Swept: from the first strip where the running winding number takes a second nonzero
    //   value (two chains that cross always make one, on one side of the crossing or the other),
    //   only the boundary of the region is kept, cut at every strip where it changes; the proven
    //   strips above are pushed as they are.
    // - TooCostly, with part of the edges pushed: the sweep would take more than `budget` steps
    //   (a chain passed in a strip, or a point passed when looking for crossings).
    // Without the outline kept, `out` holds the pushed edges already (an engine that defers its
    // accumulation, Engine::restart()): a simple shape leaves them there, any other restarts `out`
    // before its first edge.
    enum class Outcome { Simple, Swept, TooCostly };
    Outcome fill(FillRule rule, std::size_t budget, Engine& out);

private:
    struct Pt {
        double x, y;
    };
    // A run of consecutive edges of one contour going the same way up or down: its points, by y.
    struct Chain {
        std::uint32_t first, last;  // into pts_, pts_[first].y < ... < pts_[last].y
        std::int8_t dir;            // +1: the contour runs down along it, -1: up
        double xmin, xmax;          // its points' x range
    };
    // A chain spanning the proof's current y.
    struct Probe {
        double bottom;        // pts_[chain.last].y
        std::uint32_t chain;  // into chains_
        std::uint32_t seg;    // a segment at or above the current y (moved down when read)
        std::uint32_t right;  // the chain below which this one is proven not to cross, or none
        std::int8_t dir;
    };
    // A chain spanning the current strip.
    struct Active {
        double x;             // at the strip's top
        double k;             // dx / dy of its segment just below the top
        double bottom;        // pts_[chain.last].y
        double ys;            // where the current kept piece starts
        std::uint32_t seg;    // segment (pts_[seg], pts_[seg + 1]) holding the strip's top
        std::uint32_t seg_s;  // segment holding ys
        // Copied from the chain: the crossing search reads them for every pair of neighbours.
        std::uint32_t last;  // the chain's last point
        double xmin, xmax;   // the chain's x range
        std::int8_t dir;
        std::int8_t keep;  // current piece: +1 kept running down, -1 kept running up, 0 dropped
    };
    void close_chain();
    // Whether the last point is (x, y).
    bool continues(double x, double y) const {
        const Pt& p = pts_[pts_.size() - 1];
        return p.x == x && p.y == y;
    }
    // Whether the shape winds 0 and one other value only, proven without strips (see the top of
    // this file); false also when the proof cannot tell or would take more than `budget` steps.
    // Either way every strip above proven_to_ winds 0 and s_ only.
    bool prove_one_value(std::size_t budget);
    // Sets the strips up at y = proven_to_ as if they had swept the proven part above it: the
    // chains spanning y active from their tops, the others above it entered.
    void resume_strips();
    // Inserts chain c, whose top is y, where it belongs among probes_; false when it starts along
    // a chain already there (the order is then unknown).
    bool insert_probe(std::uint32_t c, double y);
    // Whether chains a (left at y) and b cross below y, over the height both span.
    bool probes_cross(Probe& a, Probe& b, double y, std::size_t& work) const;
    // The first segment from `seg` on whose end lies below y (y above the chain's bottom).
    std::uint32_t segment_below(std::uint32_t seg, double y) const {
        while (pts_[seg + 1].y <= y) ++seg;
        return seg;
    }
    // The segment of probe p that holds y (y between its top and bottom), kept in p.
    std::uint32_t segment_at(Probe& p, double y) const { return p.seg = segment_below(p.seg, y); }
    // Where p lies against the line through s0 and s1 (s0.y < s1.y), scaled by the segment's
    // height: (x_p - x_s) (s1.y - s0.y), x_s the line's x at p's height; negative on the left.
    static double side(const Pt& p, const Pt& s0, const Pt& s1) {
        return (p.x - s0.x) * (s1.y - s0.y) - (s1.x - s0.x) * (p.y - s0.y);
    }
    // Closes the open chain and opens one going `dir` from (x0, y0).
    void start_chain(double x0, double y0, std::int8_t dir);
    // Every edge of chain c into `out`, in its contour's direction times `sign`.
    void push_whole(const Chain& c, int sign, Engine& out) const;
    [[noreturn]] void too_many() const;
    // The segment's x at height y (between its ends). The share of its height comes first: the
    // slope itself overflows for an edge of subnormal height.
    double x_on(std::uint32_t seg, double y) const {
        const Pt& a = pts_[seg];
        const Pt& b = pts_[seg + 1];
        return y == a.y ? a.x : y == b.y ? b.x : a.x + (b.x - a.x) * ((y - a.y) / (b.y - a.y));
    }
    double slope(std::uint32_t seg) const { return (pts_[seg + 1].x - pts_[seg].x) / (pts_[seg + 1].y - pts_[seg].y); }
    void flush(const Active& a, double y, Engine& out) const;
    // Adds the chains whose top is y to active_.
    void enter(double y);
    // Sorts active_ at the strip's top y and returns where the strip ends: the first of `next`
    // and the crossings of neighbours.
    double strip_end(double y, double next, std::size_t& work);
    // Keeps the chains that bound the filled region in the strip from y, drops the others.
    void choose(FillRule rule, double y, Engine& out);
    // Whether the strip from y winds 0 and s only (s: the first nonzero number met, kept in s_).
    bool one_value();
    // Moves the chains to the next strip's top y; the ones ending there leave (flushed if kEmit).
    template <bool kEmit>
    void advance(double y, Engine& out);
    // The switch from proving to keeping the boundary at strip top y: the chains that ended above
    // y are pushed, the active ones keep their pieces so far.
    void take_over(double y, Engine& out);
    // The first y in (y, end] where chain a (left of b at y) is right of b, or `end`; the
    // crossing's y when there is one. Counts the points it passes in `work`.
    double first_crossing(const Active& a, const Active& b, double y, double end, std::size_t& work) const;

    // The edges as pushed, in polylines of consecutive points (x and y interleaved); outline_ends_
    // holds where each one ends, in points.
    std::vector<double> outline_;
    std::vector<std::uint32_t> outline_ends_;
    bool keep_outline_ = true;
    // Appends the edge to the last polyline when it starts where that one ends, else starts one.
    inline void keep_edge(double x0, double y0, double x1, double y1);
    // Every kept polyline into `out`, as pushed.
    void push_outline(Engine& out) const;

    AppendList<Pt> pts_;  // the open chain's in travel order, the others' by y
    std::vector<Chain> chains_;
    bool open_ = false;  // the last chain takes more points
    std::size_t count_ = 0, max_edges_ = 0;
    std::vector<std::pair<double, std::uint32_t>> order_;  // chains' tops, in order
    std::size_t next_top_ = 0;                             // the first of order_ not entered yet
    std::vector<Active> active_;                           // by x at the strip's top
    std::vector<Probe> probes_;                            // the proof's chains, by x
    int s_ = 0;                                            // the nonzero winding number of the proven strips
    double proven_to_ = 0;                                 // see prove_one_value()
};

inline void WindingSweep::keep_edge(double x0, double y0, double x1, double y1) {
    const std::size_t m = outline_.size();
    if (m != 0 && outline_[m - 2] == x0 && outline_[m - 1] == y0) {
        outline_.insert(outline_.end(), {x1, y1});
        ++outline_ends_.back();
        return;
    }
    outline_.insert(outline_.end(), {x0, y0, x1, y1});
    outline_ends_.push_back(static_cast<std::uint32_t>(m / 2 + 2));
}

inline void WindingSweep::push(double x0, double y0, double x1, double y1) {
    if (x0 == x1 && y0 == y1) return;
    if (++count_ > max_edges_) too_many();
    if (keep_outline_) keep_edge(x0, y0, x1, y1);
    if (y0 == y1) return;  // bounds no strip; the next edge starts elsewhere, so a chain ends
    const std::int8_t dir = y1 > y0 ? 1 : -1;
    if (!(open_ && chains_.back().dir == dir && continues(x0, y0))) start_chain(x0, y0, dir);
    pts_.push({x1, y1});
}

}  // namespace casteljau::raster
