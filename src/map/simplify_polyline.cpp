// Map stage: the distance search of the run simplifier (src/map/simplify_polyline.hpp).
#include "map/simplify_polyline.hpp"

#include <algorithm>
#include <limits>

namespace casteljau::map_detail {

std::pair<std::size_t, double> RunSimplifier::farthest(std::span<const Point> q, std::size_t i, std::size_t j) {
    const Point a = q[i];
    const Point d = q[j] - a;
    const double len2 = d.dot(d);
    // One division for the run, not one per point. A segment too short for its reciprocal
    // (|d| below 1e-154) is taken as the point a.
    const double inv_len2 = len2 >= std::numeric_limits<double>::min() ? 1.0 / len2 : 0.0;
    std::size_t best = i + 1;
    double best2 = -1;
    for (std::size_t k = i + 1; k < j; ++k) {
        const Point v = q[k] - a;
        // Distance to the segment: the foot of the perpendicular clamped to its ends (to the
        // point a itself when the segment has no length).
        const double t = std::clamp(v.dot(d) * inv_len2, 0.0, 1.0);
        const Point e = v - d * t;
        const double e2 = e.dot(e);
        if (e2 > best2) {
            best2 = e2;
            best = k;
        }
    }
    return {best, best2};
}

}  // namespace casteljau::map_detail
