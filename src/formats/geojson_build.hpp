// Formats stage: validation shared by the GeoJSON and TopoJSON readers.
#pragma once

#include <optional>
#include <string_view>

#include "casteljau/geojson.hpp"
#include "json/json_support.hpp"

namespace casteljau::geo_detail {

// Throws InvalidData naming `path` when |lon| > 360 or |lat| > 90 (NaN fails too).
void check_position(Point p, const json::JsonPath& path);
// The ring g.points[begin..] must hold at least 4 positions and be closed.
void check_ring(const Geometry& g, std::size_t begin, const json::JsonPath& path);
// Adds `add` to `total`; throws Limit past Limits::map_positions.
void count_positions(std::size_t& total, std::size_t add, const json::JsonPath& path);

// The geometry kind of a type name (Point, MultiPoint, LineString, ...), or nothing.
std::optional<GeometryKind> kind_of(std::string_view type);

// Reads the coordinates `c` of a geometry of `type` (any name kind_of knows) into `g`, and appends
// `g` to `f` when it holds positions. The GeoJSON and TopoJSON readers differ only in their leaves,
// which the reader `r` provides: r.path (the JSON path of `c`), r.positions (the running count),
// r.get_array(e, what), r.point(e) -> Point, r.line(e, g) and r.polygon(e, g) appending one line or
// polygon, and r.kLinesWhat naming a MultiLineString's members in errors.
template <class Reader>
void read_coordinates(Reader& r, std::string_view type, simdjson::dom::element c, Geometry& g, Feature& f) {
    // Calls each(e) for the members of array `c`, each under its index in the path.
    auto members = [&](const char* what, auto&& each) {
        std::size_t i = 0;
        for (simdjson::dom::element e : r.get_array(c, what)) {
            auto scope = r.path.index(i++);
            each(e);
        }
    };
    if (type == "Point") {
        count_positions(r.positions, 1, r.path);
        g.points.push_back(r.point(c));
    } else if (type == "MultiPoint") {
        members("an array of positions", [&](simdjson::dom::element e) {
            count_positions(r.positions, 1, r.path);
            g.points.push_back(r.point(e));
        });
    } else if (type == "LineString") {
        r.line(c, g);
    } else if (type == "MultiLineString") {
        members(Reader::kLinesWhat, [&](simdjson::dom::element e) { r.line(e, g); });
    } else if (type == "Polygon") {
        r.polygon(c, g);
    } else {
        members("an array of polygons", [&](simdjson::dom::element e) { r.polygon(e, g); });
    }
    if (!g.points.empty()) {
        g.points.shrink_to_fit();  // one exact copy of the coordinates, not up to twice that
        f.geometries.push_back(std::move(g));
    }
}

// The TopoJSON reader on an already parsed document.
MapData topojson_from(simdjson::dom::element root, std::string_view object);

}  // namespace casteljau::geo_detail
