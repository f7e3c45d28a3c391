// Formats stage: validation shared by the GeoJSON and TopoJSON readers.
#pragma once

#include "casteljau/geojson.hpp"
#include "formats/json_support.hpp"

namespace casteljau::geo_detail {

// Throws InvalidData naming `path` when |lon| > 360 or |lat| > 90 (NaN fails too).
void check_position(Point p, const json::JsonPath& path);
// The ring g.points[begin..] must hold at least 4 positions and be closed.
void check_ring(const Geometry& g, std::size_t begin, const json::JsonPath& path);
// Adds `add` to `total`; throws Limit past Limits::map_positions.
void count_positions(std::size_t& total, std::size_t add, const json::JsonPath& path);

// The TopoJSON reader on an already parsed document.
MapData topojson_from(simdjson::dom::element root, std::string_view object);

}  // namespace casteljau::geo_detail
