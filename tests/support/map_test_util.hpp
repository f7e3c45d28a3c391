// Test helpers for the map stage: an independent exact-area reference of map features under the
// equirectangular projection, built with the test's own arithmetic (antimeridian handled by
// unwrapping each ring and drawing it at -360, 0 and +360 degrees, closing polar rings along the
// pole), then tests/support/reference_area's slab integration.
#pragma once

#include <cmath>
#include <string>

#include "casteljau/geojson.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/map.hpp"
#include "reference_area.hpp"

namespace casteljau::test {

// `one` with its first layer's stroke moved to a layer of its own after it, in `colour` at the
// same width: render_map then strokes apart from the fills (no segments gathered by the fill's
// visitors, nothing swept before the fills), and the pixels must be the same.
inline MapStyle stroke_in_own_layer(const MapStyle& one, Color colour) {
    MapStyle two = one;
    two.layers[0].stroke.reset();
    two.layers[0].stroke_width = 0;
    MapLayerStyle strokes;
    strokes.fill.reset();
    strokes.stroke = colour;
    strokes.stroke_width = one.layers[0].stroke_width;
    two.layers.push_back(strokes);
    return two;
}

// Equirectangular frame of the bbox -180,-90,180,90 onto W x H pixels.
struct EquirectFrame {
    int w, h;
    Point px(double lon, double lat) const { return {(lon + 180.0) / 360.0 * w, (90.0 - lat) / 180.0 * h}; }
};

inline ref::Contours reference_contours(const Feature& f, const EquirectFrame& fr) {
    ref::Contours out;
    for (const Geometry& g : f.geometries) {
        if (g.kind != GeometryKind::Polygons) continue;
        std::size_t start = 0;
        for (std::uint32_t end : g.ring_ends) {
            std::vector<Point> u;
            for (std::size_t i = start; i + 1 < end; ++i) {  // drop the repeated closing position
                Point p = g.points[i];
                if (!u.empty()) {
                    while (p.x - u.back().x > 180) p.x -= 360;
                    while (p.x - u.back().x < -180) p.x += 360;
                }
                u.push_back(p);
            }
            // The closing step, taken the short way: does the ring come back to its start?
            double close_x = g.points[start].x;
            while (close_x - u.back().x > 180) close_x -= 360;
            while (close_x - u.back().x < -180) close_x += 360;
            if (std::fabs(close_x - u.front().x) > 1) {  // winds around a pole
                double mean = 0;
                for (const Point& p : u) mean += p.y;
                const double pole = mean < 0 ? -90 : 90;
                u.push_back({close_x, u.front().y});
                u.push_back({close_x, pole});
                u.push_back({u.front().x, pole});
            }
            for (int shift = -1; shift <= 1; ++shift) {
                ref::Contour c;
                for (const Point& p : u) c.push_back(fr.px(p.x + 360.0 * shift, p.y));
                out.push_back(std::move(c));
            }
            start = end;
        }
    }
    return out;
}

inline MapData load_world() {
    const auto bytes = read_file(std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json");
    return read_topojson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), "countries");
}

}  // namespace casteljau::test
