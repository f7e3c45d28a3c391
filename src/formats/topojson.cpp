// Formats stage: the TopoJSON reader. Arcs are delta-decoded and dequantized once into an arc
// table; rings and lines are assembled from it (the shared first/last position of consecutive arcs
// kept once). Each geometry of a top-level GeometryCollection becomes one Feature, as in
// topojson-client's feature().
#include <algorithm>
#include <cmath>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/geojson.hpp"
#include "formats/geojson_build.hpp"
#include "json/json_support.hpp"
#include "formats/json_properties.hpp"

namespace casteljau {

namespace {

using json::JsonPath;
using simdjson::dom::array;
using simdjson::dom::element;
using simdjson::dom::object;

struct TopoReader {
    JsonPath path;
    MapData& out;
    double sx = 1, sy = 1, tx = 0, ty = 0;
    bool quantized = false;
    std::size_t positions = 0;
    std::vector<bool> used;
    int depth = 0;

    explicit TopoReader(MapData& o) : out(o) {}

    array get_array(element e, const char* what) {
        array a;
        if (e.get_array().get(a) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, std::string("expected ") + what);
        return a;
    }

    double number(element e) {
        double v;
        if (e.get_double().get(v) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected a number");
        return v;
    }

    void transform(element e) {
        object t;
        if (e.get_object().get(t) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected an object");
        element s, tr;
        if (t["scale"].get(s) != simdjson::SUCCESS || t["translate"].get(tr) != simdjson::SUCCESS)
            path.fail(ErrorKind::Parse, "a transform needs \"scale\" and \"translate\"");
        array sa = get_array(s, "[sx, sy]"), ta = get_array(tr, "[tx, ty]");
        if (sa.size() != 2 || ta.size() != 2) path.fail(ErrorKind::Parse, "scale and translate need 2 numbers each");
        sx = number(sa.at(0).value_unsafe());
        sy = number(sa.at(1).value_unsafe());
        tx = number(ta.at(0).value_unsafe());
        ty = number(ta.at(1).value_unsafe());
        if (!std::isfinite(sx) || !std::isfinite(sy) || !std::isfinite(tx) || !std::isfinite(ty) || sx == 0 || sy == 0)
            path.fail(ErrorKind::InvalidData, "scale must be finite and non-zero, translate finite");
        quantized = true;
    }

    Point raw_position(element e) {
        array a = get_array(e, "a position (an array of numbers)");
        if (a.size() < 2)
            path.fail(ErrorKind::InvalidData, "a position needs 2 numbers, got " + std::to_string(a.size()));
        return {number(a.at(0).value_unsafe()), number(a.at(1).value_unsafe())};
    }

    void arcs(element e) {
        auto scope = path.key("arcs");
        array a = get_array(e, "an array of arcs");
        out.arc_ends.reserve(a.size());
        std::size_t i = 0;
        for (element arc : a) {
            auto s2 = path.index(i++);
            array pts = get_array(arc, "an arc (an array of positions)");
            if (pts.size() < 2) path.fail(ErrorKind::InvalidData, "an arc needs at least 2 positions");
            geo_detail::count_positions(positions, pts.size(), path);
            double x = 0, y = 0;
            std::size_t j = 0;
            for (element p : pts) {
                auto s3 = path.index(j++);
                const Point q = raw_position(p);
                Point g = q;
                if (quantized) {
                    x += q.x;  // delta-encoded quantized positions
                    y += q.y;
                    g = {x * sx + tx, y * sy + ty};
                }
                geo_detail::check_position(g, path);
                out.arc_points.push_back(g);
            }
            out.arc_ends.push_back(static_cast<std::uint32_t>(out.arc_points.size()));
        }
        used.assign(out.arc_ends.size(), false);
    }

    // Forgets the arc starts beyond g's positions (after rings were dropped).
    static void drop_arc_starts(Geometry& g) {
        while (!g.arc_starts.empty() && g.arc_starts.back() >= g.points.size()) g.arc_starts.pop_back();
    }

    // Appends the positions of a list of arc indices (one ring or line) to g, and where its arcs
    // start to g.arc_starts.
    // Returns false for a ring collapsed below 4 positions (not added).
    bool arc_list(element e, Geometry& g, bool ring) {
        array a = get_array(e, "an array of arc indices");
        const std::size_t begin = g.points.size();
        std::size_t i = 0;
        for (element ie : a) {
            auto s = path.index(i);
            std::int64_t k;
            if (ie.get_int64().get(k) != simdjson::SUCCESS)
                path.fail(ErrorKind::Parse, "expected an integer arc index");
            const std::int64_t idx = k < 0 ? ~k : k;
            if (idx >= static_cast<std::int64_t>(out.arc_ends.size()))
                path.fail(ErrorKind::InvalidData, "arc index " + std::to_string(k) +
                                                      " is out of range (the topology has " +
                                                      std::to_string(out.arc_ends.size()) + " arcs)");
            used[static_cast<std::size_t>(idx)] = true;
            const std::size_t a0 = idx == 0 ? 0 : out.arc_ends[static_cast<std::size_t>(idx) - 1];
            const std::size_t a1 = out.arc_ends[static_cast<std::size_t>(idx)];
            geo_detail::count_positions(positions, a1 - a0, path);
            // Consecutive arcs share their joining position: keep it once.
            const std::size_t skip = i > 0 ? 1 : 0;
            const std::size_t start = g.points.size() > begin ? g.points.size() - skip : begin;
            if (k >= 0) {
                for (std::size_t j = a0 + skip; j < a1; ++j) g.points.push_back(out.arc_points[j]);
            } else {
                for (std::size_t j = a1 - skip; j-- > a0;) g.points.push_back(out.arc_points[j]);
            }
            if (start < g.points.size() && (g.arc_starts.empty() || g.arc_starts.back() < start))
                g.arc_starts.push_back(static_cast<std::uint32_t>(start));
            ++i;
        }
        if (ring && g.points.size() - begin < 4) {
            // Quantization collapses tiny rings to fewer than 4 positions (Natural Earth 10m has
            // some): they enclose no area and are dropped.
            g.points.resize(begin);
            drop_arc_starts(g);
            return false;
        }
        if (ring) geo_detail::check_ring(g, begin, path);
        if (g.points.size() > begin) g.ring_ends.push_back(static_cast<std::uint32_t>(g.points.size()));
        return true;
    }

    void polygon(element e, Geometry& g) {
        std::size_t i = 0;
        const std::size_t points0 = g.points.size(), rings0 = g.ring_ends.size();
        bool exterior_ok = true;
        for (element r : get_array(e, "a polygon (an array of rings)")) {
            auto s = path.index(i);
            const bool ok = arc_list(r, g, true);
            if (i == 0) exterior_ok = ok;
            ++i;
        }
        if (!exterior_ok) {  // a collapsed exterior: the holes inside it go too
            g.points.resize(points0);
            g.ring_ends.resize(rings0);
            drop_arc_starts(g);
            return;
        }
        if (g.ring_ends.size() > rings0) g.polygon_ends.push_back(static_cast<std::uint32_t>(g.ring_ends.size()));
    }

    Point point(element e) {
        const Point q = raw_position(e);
        const Point g = quantized ? Point{q.x * sx + tx, q.y * sy + ty} : q;
        geo_detail::check_position(g, path);
        return g;
    }

    void geometry(object obj, Feature& f) {
        if (++depth > current_limits().nesting_depth)
            path.fail(ErrorKind::Limit, "geometry collections nested too deeply");
        element te;
        std::string_view type;
        if (obj["type"].get(te) != simdjson::SUCCESS) {
            auto s = path.key("type");
            path.fail(ErrorKind::Parse, "missing");
        }
        if (te.is_null()) {
            --depth;
            return;
        }
        if (te.get_string().get(type) != simdjson::SUCCESS) {
            auto s = path.key("type");
            path.fail(ErrorKind::Parse, "expected a string");
        }
        if (type == "GeometryCollection") {
            auto s = path.key("geometries");
            element gs;
            if (obj["geometries"].get(gs) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "missing");
            std::size_t i = 0;
            for (element ge : get_array(gs, "an array of geometries")) {
                auto s2 = path.index(i++);
                object go;
                if (ge.get_object().get(go) != simdjson::SUCCESS)
                    path.fail(ErrorKind::Parse, "expected a geometry object");
                geometry(go, f);
            }
            --depth;
            return;
        }
        Geometry g;
        const bool is_point = type == "Point" || type == "MultiPoint";
        if (const auto kind = geo_detail::kind_of(type))
            g.kind = *kind;
        else {
            auto s = path.key("type");
            path.fail(ErrorKind::Parse, "unknown geometry type \"" + std::string(type) + "\"");
        }
        const char* member = is_point ? "coordinates" : "arcs";
        auto s = path.key(member);
        element c;
        if (obj[member].get(c) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "missing");
        geo_detail::read_coordinates(*this, type, c, g, f);
        --depth;
    }

    // The leaves of read_coordinates (point() and polygon() above).
    static constexpr const char* kLinesWhat = "an array of arc lists";
    void line(element e, Geometry& g) { arc_list(e, g, false); }

    void feature(object obj) {
        Feature f;
        element e;
        if (obj["properties"].get(e) == simdjson::SUCCESS) {
            auto s = path.key("properties");
            f.properties = json::to_properties(e, path);
        }
        if (obj["id"].get(e) == simdjson::SUCCESS) f.id = json::id_text(e);
        geometry(obj, f);
        out.features.push_back(std::move(f));
    }

    // One member of "objects": a GeometryCollection gives one Feature per geometry.
    void top_object(element e) {
        object obj;
        if (e.get_object().get(obj) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected a geometry object");
        std::string_view type;
        element gs;
        if (obj["type"].get_string().get(type) == simdjson::SUCCESS && type == "GeometryCollection" &&
            obj["geometries"].get(gs) == simdjson::SUCCESS) {
            auto s = path.key("geometries");
            std::size_t i = 0;
            for (element ge : get_array(gs, "an array of geometries")) {
                auto s2 = path.index(i++);
                object go;
                if (ge.get_object().get(go) != simdjson::SUCCESS)
                    path.fail(ErrorKind::Parse, "expected a geometry object");
                feature(go);
            }
        } else {
            feature(obj);
        }
    }
};

}  // namespace

namespace geo_detail {

MapData topojson_from(element root, std::string_view object_name) {
    MapData out;
    TopoReader r(out);
    object obj;
    std::string_view type;
    if (root.get_object().get(obj) != simdjson::SUCCESS || obj["type"].get_string().get(type) != simdjson::SUCCESS ||
        type != "Topology")
        r.path.fail(ErrorKind::Parse, "expected a TopoJSON object with \"type\": \"Topology\"");
    element e;
    if (obj["transform"].get(e) == simdjson::SUCCESS) {
        auto s = r.path.key("transform");
        r.transform(e);
    }
    if (obj["arcs"].get(e) == simdjson::SUCCESS)
        r.arcs(e);
    else
        r.used.clear();
    element objs;
    object objects;
    if (obj["objects"].get(objs) != simdjson::SUCCESS || objs.get_object().get(objects) != simdjson::SUCCESS) {
        auto s = r.path.key("objects");
        r.path.fail(ErrorKind::Parse, "missing or not an object");
    }
    bool found = false;
    std::string names;
    for (auto field : objects) {
        if (!names.empty()) names += ", ";
        names += std::string(field.key);
        if (!object_name.empty() && field.key != object_name) continue;
        found = true;
        auto s = r.path.key("objects");
        auto s2 = r.path.key(field.key);
        r.top_object(field.value);
    }
    if (!object_name.empty() && !found)
        throw Error(ErrorKind::InvalidArgument,
                    "TopoJSON has no object named '" + std::string(object_name) + "' (it has: " + names + ")");
    for (std::size_t i = 0; i < r.used.size(); ++i)
        if (r.used[i]) out.used_arcs.push_back(static_cast<std::uint32_t>(i));
    return out;
}

}  // namespace geo_detail

MapData read_topojson(std::string_view text, std::string_view object) {
    simdjson::dom::parser parser;
    const element root = json::parse(parser, text, "TopoJSON");
    return geo_detail::topojson_from(root, object);
}

}  // namespace casteljau
