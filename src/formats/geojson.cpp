// Formats stage: the GeoJSON reader (RFC 7946) and its newline-delimited form. A
// FeatureCollection is checked for well-formedness in one pass and then parsed one feature at a
// time with simdjson's DOM, so that memory holds the text, the MapData (see
// include/casteljau/geojson.hpp) and the tape of a single feature; other documents are parsed whole.
#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/file_io.hpp"
#include "formats/geojson_build.hpp"
#include "json/json_support.hpp"
#include "formats/json_properties.hpp"

namespace casteljau {

namespace geo_detail {

void check_position(Point p, const json::JsonPath& path) {
    if (!(std::fabs(p.x) <= 360.0) || !(std::fabs(p.y) <= 90.0))
        path.fail(ErrorKind::InvalidData, "position (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                                              ") is outside longitude -360..360 / latitude -90..90");
}

void check_ring(const Geometry& g, std::size_t begin, const json::JsonPath& path) {
    const std::size_t n = g.points.size() - begin;
    if (n < 4) path.fail(ErrorKind::InvalidData, "a polygon ring needs at least 4 positions, got " + std::to_string(n));
    if (!(g.points[begin] == g.points.back()))
        path.fail(ErrorKind::InvalidData, "polygon ring is not closed (its last position differs from its first)");
}

void count_positions(std::size_t& total, std::size_t add, const json::JsonPath& path) {
    total += add;
    if (const std::size_t max_positions = current_limits().map_positions; total > max_positions)
        path.fail(ErrorKind::Limit, "more than " + std::to_string(max_positions) + " positions in one map");
}

std::optional<GeometryKind> kind_of(std::string_view type) {
    if (type == "Point" || type == "MultiPoint") return GeometryKind::Points;
    if (type == "LineString" || type == "MultiLineString") return GeometryKind::Lines;
    if (type == "Polygon" || type == "MultiPolygon") return GeometryKind::Polygons;
    return std::nullopt;
}

}  // namespace geo_detail

namespace {

using json::JsonPath;
using simdjson::dom::array;
using simdjson::dom::element;
using simdjson::dom::object;

struct Reader {
    JsonPath path;
    std::size_t positions = 0;
    int depth = 0;

    array get_array(element e, const char* what) {
        array a;
        if (e.get_array().get(a) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, std::string("expected ") + what);
        return a;
    }

    Point position(element e) {
        array a = get_array(e, "a position (an array of numbers)");
        if (a.size() < 2)
            path.fail(ErrorKind::InvalidData, "a position needs 2 numbers, got " + std::to_string(a.size()));
        double v[2];
        for (int k = 0; k < 2; ++k) {
            auto scope = path.index(static_cast<std::size_t>(k));
            if (a.at(static_cast<std::size_t>(k)).get_double().get(v[k]) != simdjson::SUCCESS)
                path.fail(ErrorKind::Parse, "expected a number");
        }
        const Point p{v[0], v[1]};
        geo_detail::check_position(p, path);
        return p;
    }

    // An array of positions appended to g.points.
    void positions_into(element e, Geometry& g, bool ring) {
        array a = get_array(e, ring ? "a ring (an array of positions)" : "an array of positions");
        geo_detail::count_positions(positions, a.size(), path);
        const std::size_t begin = g.points.size();
        std::size_t i = 0;
        for (element p : a) {
            auto scope = path.index(i++);
            g.points.push_back(position(p));
        }
        if (ring) geo_detail::check_ring(g, begin, path);
        g.ring_ends.push_back(static_cast<std::uint32_t>(g.points.size()));
    }

    void polygon_into(element e, Geometry& g) {
        array rings = get_array(e, "a polygon (an array of rings)");
        std::size_t i = 0;
        for (element r : rings) {
            auto scope = path.index(i++);
            positions_into(r, g, true);
        }
        if (i > 0) g.polygon_ends.push_back(static_cast<std::uint32_t>(g.ring_ends.size()));
    }

    void geometry(element e, Feature& f) {
        if (e.is_null()) return;  // a Feature without geometry
        object obj;
        if (e.get_object().get(obj) != simdjson::SUCCESS)
            path.fail(ErrorKind::Parse, "expected a geometry object or null");
        if (++depth > current_limits().nesting_depth)
            path.fail(ErrorKind::Limit, "geometry collections nested too deeply");
        std::string_view type;
        {
            auto scope = path.key("type");
            if (obj["type"].get_string().get(type) != simdjson::SUCCESS)
                path.fail(ErrorKind::Parse, "missing or not a string");
        }
        if (type == "GeometryCollection") {
            auto scope = path.key("geometries");
            element gs;
            if (obj["geometries"].get(gs) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "missing");
            std::size_t i = 0;
            for (element g : get_array(gs, "an array of geometries")) {
                auto s2 = path.index(i++);
                geometry(g, f);
            }
            --depth;
            return;
        }
        Geometry g;
        if (const auto kind = geo_detail::kind_of(type))
            g.kind = *kind;
        else {
            auto scope = path.key("type");
            path.fail(ErrorKind::Parse, "unknown geometry type \"" + std::string(type) +
                                            "\" (expected Point, MultiPoint, LineString, MultiLineString, Polygon, "
                                            "MultiPolygon or GeometryCollection)");
        }
        auto scope = path.key("coordinates");
        element c;
        if (obj["coordinates"].get(c) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "missing");
        geo_detail::read_coordinates(*this, type, c, g, f);
        --depth;
    }

    // The leaves of read_coordinates.
    static constexpr const char* kLinesWhat = "an array of lines";
    Point point(element e) { return position(e); }
    void line(element e, Geometry& g) { positions_into(e, g, false); }
    void polygon(element e, Geometry& g) { polygon_into(e, g); }

    void feature(object obj, MapData& out) {
        Feature f;
        element e;
        if (obj["geometry"].get(e) == simdjson::SUCCESS) {
            auto scope = path.key("geometry");
            geometry(e, f);
        } else {
            path.fail(ErrorKind::Parse, "a Feature needs a \"geometry\" member (null for none)");
        }
        if (obj["properties"].get(e) == simdjson::SUCCESS) {
            auto scope = path.key("properties");
            f.properties = json::to_properties(e, path);
        }
        if (obj["id"].get(e) == simdjson::SUCCESS) f.id = json::id_text(e);
        out.features.push_back(std::move(f));
    }

    // An element of a FeatureCollection's "features".
    void collection_member(element fe, MapData& out) {
        object fo;
        std::string_view ft;
        if (fe.get_object().get(fo) != simdjson::SUCCESS || fo["type"].get_string().get(ft) != simdjson::SUCCESS ||
            ft != "Feature")
            path.fail(ErrorKind::Parse, "expected an object with \"type\": \"Feature\"");
        feature(fo, out);
    }

    // The features of a FeatureCollection in `text`, each parsed on its own, so that simdjson's
    // tape (16 bytes per number, several times the text) only ever holds one feature.
    void collection(std::string_view text, const std::vector<json::RawValue>& elements, MapData& out) {
        simdjson::dom::parser parser;
        auto scope = path.key("features");
        out.features.reserve(out.features.size() + elements.size());
        std::size_t i = 0;
        for (const json::RawValue& v : elements) {
            auto s2 = path.index(i++);
            collection_member(json::parse(parser, text.substr(v.begin, v.end - v.begin), "GeoJSON"), out);
        }
    }

    // A FeatureCollection, a Feature or a bare geometry.
    void document(element root, MapData& out, bool allow_collection) {
        object obj;
        if (root.get_object().get(obj) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected a GeoJSON object");
        std::string_view type;
        if (obj["type"].get_string().get(type) != simdjson::SUCCESS) {
            auto scope = path.key("type");
            path.fail(ErrorKind::Parse, "missing or not a string");
        }
        if (type == "FeatureCollection" && allow_collection) {
            auto scope = path.key("features");
            element fs;
            if (obj["features"].get(fs) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "missing");
            array a = get_array(fs, "an array of features");
            out.features.reserve(out.features.size() + a.size());
            std::size_t i = 0;
            for (element fe : a) {
                auto s2 = path.index(i++);
                collection_member(fe, out);
            }
        } else if (type == "Feature") {
            feature(obj, out);
        } else {
            Feature f;
            geometry(root, f);
            out.features.push_back(std::move(f));
        }
    }
};

}  // namespace

namespace {

// A top-level FeatureCollection of well-formed text, as the ranges of its features; nullopt for
// any other document (or malformed text), which then goes through simdjson's DOM whole.
std::optional<std::vector<json::RawValue>> collection_elements(std::string_view text) {
    if (json::syntax_error_offset(text) != std::string_view::npos || !simdjson::validate_utf8(text.data(), text.size()))
        return std::nullopt;
    const auto members = json::raw_object_members(text);
    const json::RawValue* type = nullptr;
    const json::RawValue* features = nullptr;
    for (const auto& [key, v] : members) {  // the first of duplicate members, as simdjson's lookup does
        if (key == "type" && !type) type = &v;
        if (key == "features" && !features) features = &v;
    }
    if (!type || !features || text.substr(type->begin, type->end - type->begin) != "\"FeatureCollection\"")
        return std::nullopt;
    return json::raw_array_elements(text, *features);
}

// `elements`: collection_elements(text).
MapData geojson_document(std::string_view text, const std::optional<std::vector<json::RawValue>>& elements,
                         std::string_view what) {
    MapData out;
    Reader r;
    if (elements) {
        r.collection(text, *elements, out);
        return out;
    }
    simdjson::dom::parser parser;
    r.document(json::parse(parser, text, std::string(what)), out, true);
    return out;
}

}  // namespace

MapData read_geojson(std::string_view text) { return geojson_document(text, collection_elements(text), "GeoJSON"); }

MapData read_geojson_lines(std::string_view text) {
    simdjson::dom::parser parser;
    MapData out;
    Reader r;
    std::size_t line_no = 0, pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        ++line_no;
        const std::size_t line_start = pos;
        pos = end + 1;
        // RFC 8142 record separators and blank lines are skipped.
        std::size_t a = 0;
        while (a < line.size() && (line[a] == ' ' || line[a] == '\t' || line[a] == '\r' || line[a] == '\x1e')) ++a;
        line.remove_prefix(a);
        if (line.empty()) continue;
        const std::string where = "GeoJSON line " + std::to_string(line_no);
        element root;
        try {
            root = json::parse(parser, line, where);
        } catch (const Error& e) {
            // Add the offset in the whole file to the message.
            throw Error(e.kind(),
                        std::string(e.what()) + " (line starts at byte " + std::to_string(line_start + a) + ")");
        }
        r.path.set_prefix("line " + std::to_string(line_no) + " ");
        r.document(root, out, false);
    }
    return out;
}

namespace {

bool looks_like_lines(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size() &&
           (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n' || text[i] == '\x1e'))
        ++i;
    const std::size_t eol = text.find('\n', i);
    if (eol == std::string_view::npos) return false;
    std::string_view first = text.substr(i, eol - i);
    while (!first.empty() && (first.back() == '\r' || first.back() == ' ' || first.back() == '\t'))
        first.remove_suffix(1);
    std::size_t j = eol + 1;
    while (j < text.size() &&
           (text[j] == ' ' || text[j] == '\t' || text[j] == '\r' || text[j] == '\n' || text[j] == '\x1e'))
        ++j;
    return first.size() >= 2 && first.front() == '{' && first.back() == '}' && j < text.size() && text[j] == '{';
}

// Documents smaller than this go through simdjson's DOM whole: its tape (about three times the
// text) is small then, and the scalar scans that cut a FeatureCollection into features would cost
// more than they save (a 1 MB file: 2.5 ms of the 12 ms a `casteljau map` drawing nothing takes).
constexpr std::size_t kPiecewiseBytes = std::size_t(8) << 20;

MapData from_text(std::string_view text, std::string_view topojson_object) {
    if (looks_like_lines(text)) return read_geojson_lines(text);
    // A large FeatureCollection's features are read in parallel after a validating scan of the
    // whole text, each through a DOM of its own; a small document, one that names a TopoJSON
    // object, or one that may be a Topology skips that scan and goes through one DOM, which reads
    // any document (a GeoJSON that merely contains the word is read the same, only without the
    // parallel path).
    const bool whole = text.size() < kPiecewiseBytes || !topojson_object.empty() ||
                       text.find("\"Topology\"") != std::string_view::npos;
    if (const auto elements = whole ? std::nullopt : collection_elements(text)) {
        if (!topojson_object.empty())
            throw Error(ErrorKind::InvalidArgument, "--layer selects a TopoJSON object, but the input is GeoJSON");
        return geojson_document(text, elements, "map data");
    }
    simdjson::dom::parser parser;
    const element root = json::parse(parser, text, "map data");
    std::string_view type;
    if (root["type"].get_string().get(type) == simdjson::SUCCESS && type == "Topology")
        return geo_detail::topojson_from(root, topojson_object);
    if (!topojson_object.empty())
        throw Error(ErrorKind::InvalidArgument, "--layer selects a TopoJSON object, but the input is GeoJSON");
    MapData out;
    Reader r;
    r.document(root, out, true);
    return out;
}

}  // namespace

MapData read_map_file(const std::string& path, std::string_view topojson_object) {
    // simdjson's loader needs the file's size, which a pipe, a FIFO or a device lacks
    // (`casteljau map <(gunzip -c world.json.gz)`): read_file reads those to their end instead.
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
        const std::vector<std::uint8_t> bytes = read_file(path);
        return from_text(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), topojson_object);
    }
    if (const std::uint64_t max_bytes = current_limits().input_bytes;
        static_cast<std::uint64_t>(st.st_size) > max_bytes)
        throw Error(ErrorKind::Limit,
                    "'" + path + "' is larger than " + std::to_string(max_bytes) + " bytes (Limits::input_bytes)");
    simdjson::padded_string text;
    if (simdjson::padded_string::load(path).get(text) != simdjson::SUCCESS)
        throw Error(ErrorKind::Io, "cannot read '" + path + "'");
    return from_text(text, topojson_object);
}

MapData read_map_data(std::string_view text, std::string_view topojson_object) {
    return from_text(text, topojson_object);
}

}  // namespace casteljau
