// Map stage (internal): Douglas-Peucker simplification of one run of a polyline, in pixel space.
//
// The bound: every vertex dropped lies within `tolerance` of the segment between the two kept
// vertices around it (distance to the segment, not to its line, so spikes that double back are
// kept). The chain of original segments between two kept vertices then lies inside the capsule of
// radius `tolerance` round their segment (the capsule is convex and holds every vertex of the
// chain), and the chain crosses every perpendicular of that segment (it runs from one end to the
// other), so the simplified run and the original run are within `tolerance` of each other in both
// directions (Hausdorff distance).
//
// The result depends only on the points in the order given: two copies of one run handed over in
// the same order keep the same vertices (the caller orients shared runs canonically).
//
// Cost: runs are cut every kMaxRunPoints points (those points are kept), so the worst case (a
// spiral, where each split removes one point) costs kMaxRunPoints distance evaluations per point;
// real borders cost about log2(n) per point.
// Thread-safety: one RunSimplifier per thread.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "casteljau/geometry.hpp"

namespace casteljau::map_detail {

inline constexpr std::size_t kMaxRunPoints = 512;

class RunSimplifier {
public:
    // Marks in `keep` (keep[i] = 1, same size as `q`) the vertices of the open run q[0 .. n-1] that
    // stay: both ends, the vertex farthest from the chord of the run (so that a run with interior
    // vertices keeps at least one, and a ring of runs keeps an area), and every vertex Douglas-Peucker
    // needs at `tolerance`. When q.front() == q.back() (a closed run) the chord is a point and the
    // vertex farthest from it is kept, then the one farthest from each half's chord, so a closed run
    // keeps at least three distinct vertices. `too_long(i, j)`: true when the segment from q[i] to q[j] must not
    // replace the vertices between them whatever their distance (a projection that bends long
    // segments); it is asked only for j > i + 1.
    template <class TooLong>
    void simplify(std::span<const Point> q, double tolerance, std::span<std::uint8_t> keep, const TooLong& too_long) {
        const std::size_t n = q.size();
        if (n == 0) return;
        keep[0] = keep[n - 1] = 1;
        for (std::size_t begin = 0; begin + 1 < n;) {
            const std::size_t end = std::min(n - 1, begin + kMaxRunPoints);
            keep[end] = 1;
            split_all(q, begin, end, tolerance, keep, too_long);
            begin = end;
        }
    }

private:
    // Douglas-Peucker over q[first .. last] with an explicit stack; the first split of the run (and
    // for a closed run the first split of each half) is taken whatever the distance.
    template <class TooLong>
    void split_all(std::span<const Point> q, std::size_t first, std::size_t last, double tolerance,
                   std::span<std::uint8_t> keep, const TooLong& too_long) {
        const double tol2 = tolerance * tolerance;
        const bool closed = q[first] == q[last];
        stack_.clear();
        stack_.push_back({first, last, closed ? 2 : 1});
        while (!stack_.empty()) {
            const Pending s = stack_.back();
            stack_.pop_back();
            if (s.j <= s.i + 1) continue;
            const auto [k, d2] = farthest(q, s.i, s.j);
            if (s.forced == 0 && d2 <= tol2 && !too_long(s.i, s.j)) continue;
            keep[k] = 1;
            const int forced = s.forced == 2 ? 1 : 0;
            stack_.push_back({s.i, k, forced});
            stack_.push_back({k, s.j, forced});
        }
    }

    // The interior vertex of q(i .. j) farthest from the segment q[i] q[j] (the first of equals),
    // and its squared distance.
    static std::pair<std::size_t, double> farthest(std::span<const Point> q, std::size_t i, std::size_t j);

    struct Pending {
        std::size_t i, j;
        int forced;  // 2: split this run and both halves whatever the distance; 1: this run
    };
    std::vector<Pending> stack_;
};

}  // namespace casteljau::map_detail
