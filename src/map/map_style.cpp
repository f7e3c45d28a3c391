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

// Calls read(value) with the path at `name` when object `o` has that member.
template <class Read>
void optional_member(object o, const char* name, JsonPath& path, Read&& read) {
    element e;
    if (o[name].get(e) != simdjson::SUCCESS) return;
    auto s = path.key(name);
    read(e);
}

// A number in [lo, hi]; `range` names the range in the error.
double number_in(element e, JsonPath& path, double lo, double hi, const char* range) {
    const double v = number(e, path);
    if (v < lo || v > hi) path.fail(ErrorKind::Parse, range);
    return v;
}

std::vector<Color> palette(element e, JsonPath& path) {
    simdjson::dom::array a;
    if (e.get_array().get(a) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected an array of colours");
    std::vector<Color> colors;
    std::size_t k = 0;
    for (element c : a) {
        auto s = path.index(k++);
        colors.push_back(color_or_none(c, path).value_or(Color::transparent()));
    }
    return colors;
}

// [[MIN, COLOUR], [MAX, COLOUR]].
ColorRamp ramp(element e, JsonPath& path) {
    simdjson::dom::array a;
    if (e.get_array().get(a) != simdjson::SUCCESS || a.size() != 2)
        path.fail(ErrorKind::Parse, "expected [[MIN, COLOUR], [MAX, COLOUR]]");
    ColorRamp r;
    for (std::size_t k = 0; k < 2; ++k) {
        auto s = path.index(k);
        simdjson::dom::array stop;
        if (a.at(k).get_array().get(stop) != simdjson::SUCCESS || stop.size() != 2)
            path.fail(ErrorKind::Parse, "expected [VALUE, COLOUR]");
        const double v = number(stop.at(0).value_unsafe(), path);
        const Color c = color_or_none(stop.at(1).value_unsafe(), path).value_or(Color::transparent());
        (k == 0 ? r.min : r.max) = v;
        (k == 0 ? r.min_color : r.max_color) = c;
    }
    return r;
}

MapLayerStyle layer(element le, JsonPath& path) {
    object lo;
    if (le.get_object().get(lo) != simdjson::SUCCESS) path.fail(ErrorKind::Parse, "expected a layer object");
    MapLayerStyle l;
    optional_member(lo, "filter", path, [&](element e) { l.filter = filter(e, path); });
    optional_member(lo, "fill", path, [&](element e) { l.fill = color_or_none(e, path); });
    optional_member(lo, "stroke", path, [&](element e) { l.stroke = color_or_none(e, path); });
    optional_member(lo, "fill_by", path, [&](element e) { l.fill_by = string_of(e, path); });
    optional_member(lo, "width", path,
                    [&](element e) { l.stroke_width = number_in(e, path, 0, 1e4, "must be 0 to 10000"); });
    optional_member(lo, "opacity", path, [&](element e) { l.opacity = number_in(e, path, 0, 1, "must be 0 to 1"); });
    optional_member(lo, "palette", path, [&](element e) { l.palette = palette(e, path); });
    optional_member(lo, "ramp", path, [&](element e) { l.ramp = ramp(e, path); });
    return l;
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
    optional_member(o, "background", path,
                    [&](element e) { st.background = color_or_none(e, path).value_or(Color::transparent()); });
    optional_member(o, "point_radius", path,
                    [&](element e) { st.point_radius = number_in(e, path, 0, 1e4, "must be 0 to 10000"); });
    optional_member(o, "line_join", path, [&](element e) {
        if (!parse_line_join(string_of(e, path), st.join))
            path.fail(ErrorKind::Parse, "expected miter, miter-clip, round or bevel");
    });
    optional_member(o, "line_cap", path, [&](element e) {
        if (!parse_line_cap(string_of(e, path), st.cap)) path.fail(ErrorKind::Parse, "expected butt, round or square");
    });
    auto ls = path.key("layers");
    simdjson::dom::array layers;
    element e;
    if (o["layers"].get(e) != simdjson::SUCCESS || e.get_array().get(layers) != simdjson::SUCCESS)
        path.fail(ErrorKind::Parse, "missing or not an array of layers");
    st.layers.clear();
    std::size_t i = 0;
    for (element le : layers) {
        auto s = path.index(i++);
        st.layers.push_back(layer(le, path));
    }
    return st;
}

}  // namespace casteljau
