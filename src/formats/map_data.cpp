// Formats stage: the member functions of the map data types (include/casteljau/geojson.hpp).
#include "casteljau/geojson.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace casteljau {

namespace {

std::string number_text(double v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

}  // namespace

std::string PropertyValue::to_string() const {
    switch (type) {
        case Type::Null: return "null";
        case Type::Bool: return number != 0 ? "true" : "false";
        case Type::Number: return number_text(number);
        case Type::String:
        case Type::Json: return text;
    }
    return {};
}

const PropertyValue* Feature::property(std::string_view name) const {
    for (const auto& [k, v] : properties)
        if (k == name) return &v;
    return nullptr;
}

Rect MapData::bounds() const {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const Feature& f : features)
        for (const Geometry& g : f.geometries)
            for (const Point& p : g.points) {
                x0 = std::min(x0, p.x);
                y0 = std::min(y0, p.y);
                x1 = std::max(x1, p.x);
                y1 = std::max(y1, p.y);
            }
    if (x0 > x1) return Rect{};
    return Rect{x0, y0, x1, y1};
}

std::size_t MapData::position_count() const {
    std::size_t n = 0;
    for (const Feature& f : features)
        for (const Geometry& g : f.geometries) n += g.points.size();
    return n;
}

}  // namespace casteljau
