// casteljau/geojson.hpp: map data read from GeoJSON, newline-delimited GeoJSON and TopoJSON.
//
// Pipeline position: source. The readers turn a JSON document into MapData: features, each with
// geometries in longitude/latitude degrees (x = longitude, y = latitude, as the files store them)
// and properties. Projection, fitting and drawing happen later (map.hpp).
//
// Coordinates are kept once: every geometry stores its positions in one flat array with the index
// where each ring or line ends, and nothing else holds them (the JSON text and its parsed tree are
// released when the reader returns). TopoJSON arcs are delta-decoded and dequantized once into an
// arc table; rings are then assembled from it (a border shared by two countries is therefore stored
// twice, once in each ring, which is what a fill needs; MapData::arcs keeps the table for
// callers that want each shared border once).
//
// Validation (each failure is an Error naming the JSON path, e.g.
// `features[12].geometry.coordinates[0][3]`; malformed JSON names the byte offset):
// - Parse: not JSON; a member of the wrong JSON type; an unknown geometry "type".
// - InvalidData: a position with fewer than 2 numbers; |longitude| > 360 or |latitude| > 90
//   (longitudes in (180, 360] are accepted for data stored in 0..360); a polygon ring with fewer
//   than 4 positions or whose last position differs from its first (RFC 7946 3.1.6); a TopoJSON
//   arc index out of range.
// - Limit: collections nested deeper than Limits::nesting_depth, or more than Limits::map_positions
//   positions (casteljau/limits.hpp).
// TopoJSON rings that quantization collapsed below 4 positions enclose no area and are dropped
// (with the holes of a collapsed exterior); a GeoJSON ring below 4 positions is an error.
// Tolerated (RFC 7946 allows them): empty geometries and empty collections, `null` geometry and
// properties, extra position members (altitude), unknown members (foreign members, "bbox", "crs").
//
// Thread-safety: free functions; MapData is a value.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "casteljau/geometry.hpp"

namespace casteljau {

enum class GeometryKind : std::uint8_t { Points, Lines, Polygons };

// One geometry of one kind. Positions are (longitude, latitude) in degrees.
// Points: `points` are the points, `ring_ends` is empty.
// Lines: `ring_ends[i]` is one past the last position of line i.
// Polygons: rings as for Lines (each ring closed: last position == first), and `polygon_ends[j]`
// one past the index (into ring_ends) of the last ring of polygon j; the first ring of a polygon is
// its exterior, the others are holes.
struct Geometry {
    GeometryKind kind = GeometryKind::Points;
    std::vector<Point> points;
    std::vector<std::uint32_t> ring_ends;
    std::vector<std::uint32_t> polygon_ends;
    // TopoJSON only (empty otherwise): the indices into `points`, in order, where a ring or line
    // begins an arc, that is each ring's or line's first position and every position two
    // consecutive arcs share. A border two features share is one arc, so these are where shared
    // borders begin and end.
    std::vector<std::uint32_t> arc_starts;
};

struct PropertyValue {
    enum class Type : std::uint8_t { Null, Bool, Number, String, Json } type = Type::Null;
    double number = 0;  // Number; Bool as 0/1
    std::string text;   // String: the string; Json: the minified JSON of an object or array
    // The value as text: strings as is, numbers in shortest form, true/false/null, JSON as JSON.
    std::string to_string() const;
};

struct Feature {
    std::string id;                                                 // the "id" member as text ("" when absent)
    std::vector<std::pair<std::string, PropertyValue>> properties;  // in file order
    std::vector<Geometry> geometries;  // a GeometryCollection gives several (nested ones flattened)
    const PropertyValue* property(std::string_view name) const;  // nullptr when absent
};

struct MapData {
    std::vector<Feature> features;  // in file order
    // TopoJSON only: the decoded arcs (positions in degrees), arc i = arc_points[arc_ends[i-1] .. arc_ends[i]),
    // and for every feature the arcs its rings use (each arc once, unsigned index).
    std::vector<Point> arc_points;
    std::vector<std::uint32_t> arc_ends;
    std::vector<std::uint32_t> used_arcs;  // arcs used by the read objects, each listed once
    Rect bounds() const;                   // of every position (empty Rect when there is none)
    std::size_t position_count() const;
};

// GeoJSON text: a FeatureCollection, a Feature or a bare geometry (RFC 7946).
MapData read_geojson(std::string_view json);
// Newline-delimited GeoJSON: one Feature (or geometry) per non-blank line; errors name the line.
MapData read_geojson_lines(std::string_view text);
// TopoJSON text (a "Topology"). `object` selects one member of "objects" by name; empty reads
// every object in file order. Throws Error(InvalidArgument) when `object` is not there.
MapData read_topojson(std::string_view json, std::string_view object = {});
// Chooses by content: {"type":"Topology"} -> TopoJSON; several lines that each hold a JSON
// object -> GeoJSON lines; otherwise GeoJSON.
MapData read_map_data(std::string_view text, std::string_view topojson_object = {});
// The same from a file, with less memory: the file is read once into a padded buffer that simdjson
// parses in place, and released as soon as it is parsed (peak: the file + simdjson's parsed tree,
// then the tree + the MapData); a pipe, FIFO or device is read to its end (read_file) and parsed
// from a copy. Throws Error(Io) when the file cannot be read, Error(Limit) when it is larger than
// Limits::input_bytes.
MapData read_map_file(const std::string& path, std::string_view topojson_object = {});

}  // namespace casteljau
