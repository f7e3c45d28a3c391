// Map stage: the JSON style file (format in include/casteljau/map.hpp).
#include <cmath>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/map.hpp"
#include "json/json_support.hpp"
#include "formats/json_properties.hpp"

namespace casteljau {

namespace {

using json::JsonPath;
using simdjson::dom::element;
using simdjson::dom::object;

std::optional<Color> color_or_none(element e, JsonPath& path) {
    if (e.is_null()) return std::nullopt;
    std::string_view s;
    if (e.get_string().get(s) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected a colour string or null");
    try {
        const Color c = parse_color(s);
        if (s == "none") return std::nullopt;
        return c;
    } catch (const Error& err) { path.fail(ErrorKind::Parse, err.what()); }
}

double number(element e, JsonPath& path) {
    double v;
    if (e.get_double().get(v) != simdjson::SUCCESS || !std::isfinite(v))
        path.fail(ErrorKind::Parse, "expected a finite number");
    return v;
}

std::string string_of(element e, JsonPath& path) {
    std::string_view s;
    if (e.get_string().get(s) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected a string");
    return std::string(s);
}

MapFilter filter(element e, JsonPath& path) {
    MapFilter f;
    object o;
    if (e.get_object().get(o) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected an object");
    element v;
    {
        auto s = path.key("property");
        if (o["property"].get(v) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "missing");
        f.property = string_of(v, path);
    }
    struct OpName {
        const char* name;
        MapFilter::Op op;
    };
    const OpName ops[] = {{"==", MapFilter::Op::Equals}, {"!=", MapFilter::Op::NotEquals}, {"<", MapFilter::Op::Less},
                          {">", MapFilter::Op::Greater}, {"in", MapFilter::Op::In},        {"has", MapFilter::Op::Has}};
    for (const OpName& op : ops) {
        if (o[op.name].get(v) != simdjson::SUCCESS) continue;
        auto s = path.key(op.name);
        f.op = op.op;
        if (op.op == MapFilter::Op::In) {
            simdjson::dom::array a;
            if (v.get_array().get(a) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected an array of values");
            for (element x : a) f.values.push_back(json::to_property(x));
        } else if (op.op != MapFilter::Op::Has) {
            f.values.push_back(json::to_property(v));
        }
        return f;
    }
    path.fail(ErrorKind::Parse, "a filter needs one of ==, !=, <, >, in, has");
}

}  // namespace

MapStyle read_map_style(std::string_view text) {
    simdjson::dom::parser parser;
    const element root = json::parse(parser, text, "style");
    JsonPath path;
    path.set_prefix("style ");
    object o;
    if (root.get_object().get(o) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected an object");
    MapStyle st;
    element e;
    if (o["background"].get(e) == simdjson::SUCCESS) {
        auto s = path.key("background");
        st.background = color_or_none(e, path).value_or(Color::transparent());
    }
    if (o["point_radius"].get(e) == simdjson::SUCCESS) {
        auto s = path.key("point_radius");
        st.point_radius = number(e, path);
        if (st.point_radius < 0 || st.point_radius > 1e4) path.fail(ErrorKind::Parse, "must be 0 to 10000");
    }
    if (o["line_join"].get(e) == simdjson::SUCCESS) {
        auto s = path.key("line_join");
        if (!parse_line_join(string_of(e, path), st.join))
            path.fail(ErrorKind::Parse, "expected miter, miter-clip, round or bevel");
    }
    if (o["line_cap"].get(e) == simdjson::SUCCESS) {
        auto s = path.key("line_cap");
        if (!parse_line_cap(string_of(e, path), st.cap)) path.fail(ErrorKind::Parse, "expected butt, round or square");
    }
    auto ls = path.key("layers");
    simdjson::dom::array layers;
    if (o["layers"].get(e) != simdjson::SUCCESS || e.get_array().get(layers) != simdjson::SUCCESS)
        path.fail(ErrorKind::Parse, "missing or not an array of layers");
    st.layers.clear();
    std::size_t i = 0;
    for (element le : layers) {
        auto s = path.index(i++);
        object lo;
        if (le.get_object().get(lo) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected a layer object");
        MapLayerStyle l;
        if (lo["filter"].get(e) == simdjson::SUCCESS) {
            auto s2 = path.key("filter");
            l.filter = filter(e, path);
        }
        if (lo["fill"].get(e) == simdjson::SUCCESS) {
            auto s2 = path.key("fill");
            l.fill = color_or_none(e, path);
        }
        if (lo["stroke"].get(e) == simdjson::SUCCESS) {
            auto s2 = path.key("stroke");
            l.stroke = color_or_none(e, path);
        }
        if (lo["fill_by"].get(e) == simdjson::SUCCESS) {
            auto s2 = path.key("fill_by");
            l.fill_by = string_of(e, path);
        }
        if (lo["width"].get(e) == simdjson::SUCCESS) {
            auto s2 = path.key("width");
            l.stroke_width = number(e, path);
            if (l.stroke_width < 0 || l.stroke_width > 1e4) path.fail(ErrorKind::Parse, "must be 0 to 10000");
        }
        if (lo["opacity"].get(e) == simdjson::SUCCESS) {
            auto s2 = path.key("opacity");
            l.opacity = number(e, path);
            if (l.opacity < 0 || l.opacity > 1) path.fail(ErrorKind::Parse, "must be 0 to 1");
        }
        if (lo["palette"].get(e) == simdjson::SUCCESS) {
            auto s2 = path.key("palette");
            simdjson::dom::array a;
            if (e.get_array().get(a) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected an array of colours");
            std::size_t k = 0;
            for (element c : a) {
                auto s3 = path.index(k++);
                l.palette.push_back(color_or_none(c, path).value_or(Color::transparent()));
            }
        }
        if (lo["ramp"].get(e) == simdjson::SUCCESS) {
            auto s2 = path.key("ramp");
            simdjson::dom::array a;
            if (e.get_array().get(a) != simdjson::SUCCESS || a.size() != 2)
                path.fail(ErrorKind::Parse, "expected [[MIN, COLOUR], [MAX, COLOUR]]");
            ColorRamp r;
            for (std::size_t k = 0; k < 2; ++k) {
                auto s3 = path.index(k);
                simdjson::dom::array stop;
                if (a.at(k).get_array().get(stop) != simdjson::SUCCESS || stop.size() != 2)
                    path.fail(ErrorKind::Parse, "expected [VALUE, COLOUR]");
                const double v = number(stop.at(0).value_unsafe(), path);
                const Color c = color_or_none(stop.at(1).value_unsafe(), path).value_or(Color::transparent());
                if (k == 0) {
                    r.min = v;
                    r.min_color = c;
                } else {
                    r.max = v;
                    r.max_color = c;
                }
            }
            l.ramp = r;
        }
        st.layers.push_back(std::move(l));
    }
    return st;
}

}  // namespace casteljau
